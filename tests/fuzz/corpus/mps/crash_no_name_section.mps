* thrustsched free MPS export of 'max_knapsack_offset'
* The mode thrustsched free MPS export of 'max_knapsack_offset'
* The model MAXIMISES; written as the minimisation of the negated objective
* (negate theax_knapsackUoffset  FREE
ROWS
 N  OBJ
 L  w1
 L  w2
 L  w3
COLUMNS
    MARKER00  'MARKER'  'INTO'GR
    a  OBJ  -5
    a  w1  2
    a  w2  4
    a  w3  3
    b  OBJ  -4
    b  w1  3
    b  c  w3  2
    MARKER00  'MARKER'  'INTEND'
    OBJ_CONST  OBJ  2.5
RHS
    RHS  w1  5
    RHS  w2  11
    RHS  w3  8
BOUNDS
 LO BND  a  0
 UP BND  a  1
 LO BND  b  0
 UP BND  b  1
 LO BND  c  0
 UP DNB  c  1
 FX BND  OBJ_CONST  1
ENDATA
