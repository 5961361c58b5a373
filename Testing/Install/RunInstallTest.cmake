# cmake -P script: install, build a consumer against the install, run it.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}")
  endif ()
endfunction()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
run("${CMAKE_COMMAND}" -S "${APP_SOURCE_DIR}" -B "${WORK_DIR}/app" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/app")
set(ENV{LD_LIBRARY_PATH} "${prefix}/lib:$ENV{LD_LIBRARY_PATH}")
execute_process(COMMAND "${WORK_DIR}/app/shapesplines_consumer" "${DATA_FILE}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output)
message("${output}")
# 32 spans x 10 subdivisions + 1 samples; helix curvature 0.4 (a C2 cubic at 8 points per turn).
if (NOT result EQUAL 0 OR NOT output MATCHES "helix.vtp: 1 line\\(s\\), 321 points, curvature 0\\.[34]")
  message(FATAL_ERROR "the consumer application failed or printed something unexpected")
endif ()
