Optimal - objective value 1
 1e300 x_x_m_1 1 0
