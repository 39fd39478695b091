* thrustsche negative_upper_bound  FREE
ROWS
 N  OBJ
 L  r
COLUMNS
    z  OBJ  -1
           negative_upper_bound  FREE
ROWS
 N  OBJ
 L  r
COLUMNS
    z  OBJ  -1
    z  r  1
    MARKER00  'MARKER'  'INTORG'
    k  r  -1
   2MARKER00  'MARKER'  'INTEND'
RHS
    RHS  r  -1.5
BOUNDS
 LO BND  z  -5
 UP BND  z  -3
 LO BND  k  -4
 UP BND  k  -1
ENDATA
