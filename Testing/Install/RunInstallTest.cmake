# cmake -P script: install, run the installed command, build a consumer
# against the install, run it.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
# As on a user's machine: the installed programs find their libraries
# themselves, not through the environment.
unset(ENV{LD_LIBRARY_PATH})

include("${CMAKE_CURRENT_LIST_DIR}/Run.cmake")

# Installed, then moved: nothing may depend on where the install went first.
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/installed")
file(RENAME "${WORK_DIR}/installed" "${prefix}")

# The installed command, as a user first runs it.
set(command "${prefix}/${INSTALL_BINDIR}/shapesplines")
execute_process(COMMAND "${command}" --help
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if (NOT result EQUAL 0 OR NOT output MATCHES "^shapesplines: ")
  message(FATAL_ERROR "the installed ${command} --help failed (${result}): ${error}")
endif ()
execute_process(COMMAND "${command}" fit "${DATA_FILE}" -o "${WORK_DIR}/helix-curve.csv" --samples 10 --quiet
  RESULT_VARIABLE result ERROR_VARIABLE error)
# 32 spans x 10 subdivisions + 1 samples, a header row, a row per sample.
file(STRINGS "${WORK_DIR}/helix-curve.csv" rows)
list(LENGTH rows row_count)
list(GET rows 0 header)
if (NOT result EQUAL 0 OR NOT row_count EQUAL 322 OR NOT header MATCHES "^line_id,x,y,z,")
  message(FATAL_ERROR "the installed command's fit failed (${result}) or wrote ${row_count} rows: ${error}")
endif ()
message("installed command: fit wrote ${row_count} rows (${header})")

run("${CMAKE_COMMAND}" -S "${APP_SOURCE_DIR}" -B "${WORK_DIR}/app" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/app")
execute_process(COMMAND "${WORK_DIR}/app/shapesplines_consumer" "${DATA_FILE}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output)
message("${output}")
# 32 spans x 10 subdivisions + 1 samples; helix curvature 0.4 (a C2 cubic at 8 points per turn).
if (NOT result EQUAL 0 OR NOT output MATCHES "helix.vtp: 1 line\\(s\\), 321 points, curvature 0\\.[34]")
  message(FATAL_ERROR "the consumer application failed or printed something unexpected")
endif ()
