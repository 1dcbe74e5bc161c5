# Finds what the Python module needs (an interpreter with NumPy, its headers,
# pybind11) and sets EXPMAP_PYTHON_FOUND. The interpreter is the first of
# python3 on PATH and /usr/bin/python3 that imports numpy: a pyenv or conda
# python3 ahead on PATH often lacks the Debian packages the module and its
# tests use. -DPython3_EXECUTABLE=... overrides the choice.
set(EXPMAP_PYTHON_FOUND FALSE)
if(NOT DEFINED Python3_EXECUTABLE)
  find_program(EXPMAP_PATH_PYTHON3 python3)
  mark_as_advanced(EXPMAP_PATH_PYTHON3)
  foreach(candidate ${EXPMAP_PATH_PYTHON3} /usr/bin/python3)
    if(EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy"
                      RESULT_VARIABLE has_numpy OUTPUT_QUIET ERROR_QUIET)
      if(has_numpy EQUAL 0)
        set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH "Python interpreter for the expmap module")
        break()
      endif()
    endif()
  endforeach()
endif()
# Development.Module (headers only, no libpython) needs CMake 3.18.
if(CMAKE_VERSION VERSION_LESS 3.18)
  set(expmap_python_development Development)
else()
  set(expmap_python_development Development.Module)
endif()
find_package(Python3 COMPONENTS Interpreter ${expmap_python_development} NumPy QUIET)
if(Python3_FOUND)
  find_package(pybind11 CONFIG QUIET)
endif()
if(Python3_FOUND AND pybind11_FOUND)
  set(EXPMAP_PYTHON_FOUND TRUE)
  message(STATUS "expmap Python module: ${Python3_EXECUTABLE}, pybind11 ${pybind11_VERSION}")
else()
  message(STATUS "expmap Python module: skipped (needs python3 with NumPy, python3-dev and "
                 "pybind11-dev; scripts/install-dependencies.sh installs them)")
endif()
