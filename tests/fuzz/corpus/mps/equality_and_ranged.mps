* thrustsched free MPS export of 'equality_and_ranged'
* Objective: minimise.
NAME          equality_and_ranged  FREE
ROWS
 N  OBJ
 E  eq
 G  rng
COLUMNS
    x  OBJ  1
    x  eq  1
    MARKER00  'MARKER'  'INTORG'
    y  OBJ  2
    y  eq  1
    y  rng  1
    MARKER00  'MARKER'  'INTEND'
    z  OBJ  1
    z  rng  -1
RHS
    RHS  eq  3
    RHS  rng  1
RANGES
    RNG  rng  1
BOUNDS
 LO BND  x  0
 UP BND  x  2.5
 LO BND  y  0
 PL BND  y
ENDATA
