Optimal - objective value 1
 0 no_such_column 1 0
