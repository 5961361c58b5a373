# cmake -P script: configure the project with the tests off and build the
# plugin; the cache must hold none of the test tools (GoogleTest, pvpython,
# xvfb-run, clang), so a machine with only the ParaView SDK and Eigen can.
# Then configure with the tests on and the tools hidden: their tests are left
# out, each group with a message.
cmake_minimum_required(VERSION 3.16)
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

# The tests on, with their tools hidden: PATH becomes a folder of links to
# everything on it but pvpython, pvbatch, paraview, xvfb-run, mpiexec and
# clang++, and GoogleTest is disabled. The configure must succeed, say which
# tools are missing and which tests it leaves out, and leave them out.
set(hidden_dir "${WORK_DIR}-hidden")
set(path_dir "${hidden_dir}-path")
file(REMOVE_RECURSE "${hidden_dir}" "${path_dir}")
file(MAKE_DIRECTORY "${path_dir}")
set(hidden_tools pvpython pvbatch paraview xvfb-run mpiexec mpirun)
string(REPLACE ":" ";" path_entries "$ENV{PATH}")
foreach (entry IN LISTS path_entries)
  file(GLOB programs LIST_DIRECTORIES false "${entry}/*")
  # A name with a bracket (/usr/bin/[) would join the rest of the list into one item.
  string(REGEX REPLACE "[^;]*[][][^;]*;?" "" programs "${programs}")
  foreach (program IN LISTS programs)
    get_filename_component(name "${program}" NAME)
    if (NOT name IN_LIST hidden_tools AND NOT name MATCHES "^clang\\+\\+" AND NOT EXISTS "${path_dir}/${name}")
      file(CREATE_LINK "${program}" "${path_dir}/${name}" SYMBOLIC)
    endif ()
  endforeach ()
endforeach ()
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env "PATH=${path_dir}"
          "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${hidden_dir}" -G "${GENERATOR}"
          -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message(STATUS "configure with the test tools hidden:\n${output}")
if (NOT result EQUAL 0)
  message(FATAL_ERROR "a configure with the test tools hidden failed (${result})")
endif ()
foreach (tool IN ITEMS "GoogleTest" "pvpython" "pvbatch" "paraview \\(the GUI\\)" "xvfb-run"
    "clang\\+\\+ with libFuzzer")
  if (NOT output MATCHES "ShapeSplines: [^\n]*${tool}[^\n]* not found: leaving out ")
    message(FATAL_ERROR "no message that ${tool} is missing and which tests are left out")
  endif ()
endforeach ()
execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" -N WORKING_DIRECTORY "${hidden_dir}"
  OUTPUT_VARIABLE tests)
if (tests MATCHES "(pvpython|pvbatch|gui|Fuzz|Image|Math|Filters)\\.[A-Za-z]+")
  message(FATAL_ERROR "${CMAKE_MATCH_0} is a test, though its tools are hidden:\n${tests}")
endif ()
if (NOT tests MATCHES "python\\.ArrayNames")
  message(FATAL_ERROR "the tests whose tools are there are missing:\n${tests}")
endif ()
file(REMOVE_RECURSE "${path_dir}")
