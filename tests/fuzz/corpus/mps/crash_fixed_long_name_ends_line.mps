NAME          CUT
ROWS
 N  COST
 L  LIM1
COLUMNS
    MARKER                 'MARKER'                 'INTORG'
    X3        COSINTORG'
ENDATA
