# Finds the Python interpreter the module is built for and pybind11 (Debian pybind11-dev).
# Debian's /usr/bin/python3 is preferred over any other python3 on PATH (pyenv, venvs), since
# the module must match the interpreter that imports it; -DPython_EXECUTABLE=... overrides.
# Sets CORDGRASP_PYTHON_MODULE (ON when the module is built) and CORDGRASP_PYTHON_INSTALL_DIR.
set(CORDGRASP_PYTHON_MODULE OFF)
if(CORDGRASP_BUILD_PYTHON)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python the module is built for")
  endif()
  find_package(Python 3 COMPONENTS Interpreter Development.Module)
  if(Python_FOUND)
    set(PYBIND11_FINDPYTHON ON)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(CORDGRASP_PYTHON_MODULE ON)
    message(STATUS
            "cordgrasp: Python module for ${Python_EXECUTABLE} (pybind11 ${pybind11_VERSION})")
  else()
    message(STATUS "cordgrasp: no Python module (needs python3-dev and pybind11-dev)")
  endif()
endif()
set(_cordgrasp_python_dir "lib/python3/dist-packages")
if(Python_FOUND)
  set(_cordgrasp_python_dir
      "lib/python${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}/dist-packages")
endif()
set(CORDGRASP_PYTHON_INSTALL_DIR "${_cordgrasp_python_dir}" CACHE STRING
    "Where the Python package cordgrasp is installed, relative to the prefix")
