# Fails unless README.md contains the file SOURCE verbatim (examples/quickstart.cc,
# examples/python/quickstart.py).
file(READ "${README}" readme)
file(READ "${SOURCE}" source)
string(FIND "${readme}" "${source}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "README.md does not contain ${SOURCE} verbatim; update the README")
endif()
message(STATUS "README quick start matches ${SOURCE}")
