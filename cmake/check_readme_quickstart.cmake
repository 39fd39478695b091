# Fails unless README.md contains examples/quickstart.cc verbatim.
file(READ "${README}" readme)
file(READ "${SOURCE}" source)
string(FIND "${readme}" "${source}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "README.md does not contain examples/quickstart.cc verbatim; update the README")
endif()
message(STATUS "README quick start matches examples/quickstart.cc")
