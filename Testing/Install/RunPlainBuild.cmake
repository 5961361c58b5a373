# cmake -P script: configure the project with the tests off and build the
# plugin; the cache must hold none of the test tools (GoogleTest, pvpython,
# xvfb-run, clang), so a machine with only the ParaView SDK and Eigen can.
file(REMOVE_RECURSE "${WORK_DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/Run.cmake")

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF)
file(STRINGS "${WORK_DIR}/CMakeCache.txt" looked_up
  REGEX "^(GTest_DIR|PVPYTHON_EXECUTABLE|XVFB_RUN_EXECUTABLE|SYSTEM_PYTHON_EXECUTABLE)[:=]")
if (looked_up)
  message(FATAL_ERROR "a configure without tests looked up test tools: ${looked_up}")
endif ()
run("${CMAKE_COMMAND}" --build "${WORK_DIR}" --target ShapeSplines)
file(GLOB_RECURSE plugin "${WORK_DIR}/*/ShapeSplines.so")
if (NOT plugin)
  message(FATAL_ERROR "no ShapeSplines.so under ${WORK_DIR}")
endif ()
message(STATUS "built ${plugin} with the tests off")
