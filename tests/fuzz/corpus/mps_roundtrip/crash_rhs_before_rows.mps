* thrustsched e-20 r 1e-300
RHS
 RHS r 1
B   LIM2       y 0.UM UP BND y 1.7
ENDATA
    x  eq  1
    MARKER00  'MARKER'  'INTORG'
    y  OBJ  2
    y  eq  1
    y  rng  2
    MARKER00  'MARKER'N  'INTEND'
    z A