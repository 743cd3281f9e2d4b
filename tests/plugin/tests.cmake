# End-to-end tests of the Gmsh front ends, included from plugin/CMakeLists.txt (the targets are
# defined there). Python drivers run with the interpreter the module was built for; the GUI ones
# under xvfb-run, one at a time (RESOURCE_LOCK: parallel `xvfb-run -a` can race for a display).
# Screenshots are kept in <build>/artifacts/gmsh/.
set(_dir ${CMAKE_SOURCE_DIR}/tests/plugin)
set(_artifacts ${CMAKE_BINARY_DIR}/artifacts/gmsh)
find_program(CVTMESH_XVFB_RUN xvfb-run)

if(TARGET cvtmesh_python)
  add_test(NAME plugin.scripting COMMAND ${Python3_EXECUTABLE} ${_dir}/scripting_test.py)
  set_tests_properties(plugin.scripting PROPERTIES TIMEOUT 600 ENVIRONMENT
    "PYTHONPATH=${CVTMESH_PYTHON_DIR};CVTMESH_SOURCE_DIR=${CMAKE_SOURCE_DIR};CVTMESH_CLI=$<TARGET_FILE:cvtmesh>;CVTMESH_CPP_EXAMPLE=$<TARGET_FILE:cvtmesh_example_optimize>")
  add_test(NAME plugin.inprocess_inputs COMMAND ${Python3_EXECUTABLE} ${_dir}/inprocess_inputs_test.py)
  set_tests_properties(plugin.inprocess_inputs PROPERTIES TIMEOUT 600 ENVIRONMENT
    "PYTHONPATH=${CVTMESH_PYTHON_DIR}")
endif()

if(CVTMESH_XVFB_RUN)
  set(_xvfb ${CVTMESH_XVFB_RUN} -a -s "-screen 0 1280x900x24")
  add_test(NAME plugin.gui COMMAND ${_xvfb} ${Python3_EXECUTABLE} ${_dir}/gui_test.py)
  set_tests_properties(plugin.gui PROPERTIES TIMEOUT 600 RESOURCE_LOCK xvfb ENVIRONMENT
    "CVTMESH_GUI=$<TARGET_FILE:cvtmesh-gui>;CVTMESH_SOURCE_DIR=${CMAKE_SOURCE_DIR};CVTMESH_ARTIFACTS=${_artifacts}")
  if(TARGET cvtmesh-onelab)
    add_test(NAME plugin.onelab COMMAND ${_xvfb} ${Python3_EXECUTABLE} ${_dir}/onelab_test.py)
    set_tests_properties(plugin.onelab PROPERTIES TIMEOUT 600 RESOURCE_LOCK xvfb ENVIRONMENT
      "CVTMESH_ONELAB=$<TARGET_FILE:cvtmesh-onelab>;CVTMESH_CLI=$<TARGET_FILE:cvtmesh>;CVTMESH_SOURCE_DIR=${CMAKE_SOURCE_DIR};CVTMESH_ARTIFACTS=${_artifacts}")
  endif()
else()
  message(${CVTMESH_MISSING_LEVEL} "cvtmesh: xvfb-run not found: the Gmsh GUI tests are not registered")
endif()
