# Builds a fuzz target with clang++ and runs it for a bounded time:
#   cmake -DSOURCE_DIR=<repo root> -DWORK_DIR=<build dir> [-DSECONDS=60]
#         [-DFUZZ_TARGET=fuzz_fit|fuzz_filters] [-DParaView_DIR=<dir> (fuzz_filters)]
#         [-DCXX_COMPILER=clang++] [-DREGRESSIONS=OFF] [-DFUZZ_ARGS="-seed=1;-max_len=2048"]
#         -P RunFuzz.cmake
# 1. configures and builds Testing/Fuzz's FUZZ_TARGET (default fuzz_fit, the math core;
#    fuzz_filters is the VTK layer) in WORK_DIR/build;
# 2. runs every file of the target's regressions (Testing/Fuzz/regressions/ for
#    fuzz_fit, Testing/Fuzz/filters/regressions/ for fuzz_filters) once, and for
#    fuzz_fit those of regressions/extra/ too when FUZZ_FIT_EXTRA=1 is in the environment;
# 3. unless SECONDS is 0, fuzzes for SECONDS seconds from WORK_DIR/corpus (new inputs
#    are kept there between runs) and the target's seed corpus (Testing/Fuzz/corpus,
#    Testing/Fuzz/filters/corpus).
# Any failure is a FATAL_ERROR showing libFuzzer's last lines; libFuzzer leaves the
# failing input as WORK_DIR/crash-* (or timeout-*, oom-*, leak-*), whose path is printed.
# fuzz_fit reads FUZZ_FIT_EXTRA, FUZZ_FIT_EXPONENT_LIMIT and FUZZ_FIT_VERBOSE from the
# environment (see fuzz_fit.cxx); set them with the test's ENVIRONMENT property.
cmake_minimum_required(VERSION 3.16)

foreach (required SOURCE_DIR WORK_DIR)
  if (NOT DEFINED ${required})
    message(FATAL_ERROR "RunFuzz.cmake: pass -D${required}=...")
  endif ()
endforeach ()
if (NOT DEFINED SECONDS OR SECONDS STREQUAL "")
  set(SECONDS 60)
endif ()
if (NOT DEFINED CXX_COMPILER OR CXX_COMPILER STREQUAL "")
  find_program(CXX_COMPILER NAMES clang++ clang++-14 clang++-15 clang++-16)
  if (NOT CXX_COMPILER)
    message(FATAL_ERROR "RunFuzz.cmake: clang++ not found (Debian 12: apt-get install clang libclang-rt-14-dev)")
  endif ()
endif ()
get_filename_component(SOURCE_DIR "${SOURCE_DIR}" ABSOLUTE)
get_filename_component(WORK_DIR "${WORK_DIR}" ABSOLUTE)
if (NOT DEFINED FUZZ_TARGET OR FUZZ_TARGET STREQUAL "")
  set(FUZZ_TARGET fuzz_fit)
endif ()
set(fuzz_source_dir "${SOURCE_DIR}/Testing/Fuzz")
set(build_dir "${WORK_DIR}/build")
set(work_corpus "${WORK_DIR}/corpus")
set(configure_options "")
if (FUZZ_TARGET STREQUAL "fuzz_filters")
  set(seed_corpus "${fuzz_source_dir}/filters/corpus")
  set(regression_dir "${fuzz_source_dir}/filters/regressions")
  list(APPEND configure_options -DFUZZ_FILTERS=ON)
  if (DEFINED ParaView_DIR)
    list(APPEND configure_options "-DParaView_DIR=${ParaView_DIR}")
  endif ()
else ()
  set(seed_corpus "${fuzz_source_dir}/corpus")
  set(regression_dir "${fuzz_source_dir}/regressions")
endif ()
file(MAKE_DIRECTORY "${WORK_DIR}" "${work_corpus}")

# Prints the last `count` lines of a log and fails.
function(fuzz_fail what log_file count)
  # The last `count` lines, found from the end (no list handling: logs hold ; and [).
  file(READ "${log_file}" tail)
  string(REGEX REPLACE "\n+$" "" tail "${tail}")
  set(rest "${tail}")
  foreach (i RANGE 1 ${count})
    string(FIND "${rest}" "\n" position REVERSE)
    if (position LESS 0)
      break()
    endif ()
    string(SUBSTRING "${rest}" 0 ${position} rest)
  endforeach ()
  if (position GREATER_EQUAL 0)
    math(EXPR position "${position} + 1")
    string(SUBSTRING "${tail}" ${position} -1 tail)
  endif ()
  file(GLOB artifacts "${WORK_DIR}/crash-*" "${WORK_DIR}/timeout-*" "${WORK_DIR}/oom-*"
    "${WORK_DIR}/leak-*" "${WORK_DIR}/slow-unit-*")
  set(found "")
  foreach (artifact IN LISTS artifacts)
    if (NOT artifact IN_LIST ARGN) # ARGN: artifacts that existed before this run
      string(APPEND found "  ${artifact}\n")
    endif ()
  endforeach ()
  if (found)
    string(TOUPPER "${FUZZ_TARGET}" verbose)
    set(found "Failing input(s) kept (reproduce: ${verbose}_VERBOSE=1 ${build_dir}/${FUZZ_TARGET} <file>):\n${found}")
  endif ()
  # The diagnosis lines, wherever they are in a long report.
  file(STRINGS "${log_file}" key REGEX
    "(INVARIANT FAILED|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY:|Test unit written)")
  list(JOIN key "\n" key)
  # NOTICE prints the lines as they are; FATAL_ERROR would rewrap them.
  message(NOTICE "--- last ${count} lines of ${log_file} ---\n${tail}\n--- end ---\n"
    "${key}\n${found}")
  message(FATAL_ERROR "${what} failed; full log: ${log_file}")
endfunction()

# 1. Configure and build.
string(TIMESTAMP start "%s")
set(build_log "${WORK_DIR}/build.log")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -S "${fuzz_source_dir}" -B "${build_dir}"
          "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DSHAPESPLINES_SOURCE_DIR=${SOURCE_DIR}"
          ${configure_options}
  RESULT_VARIABLE result OUTPUT_FILE "${build_log}" ERROR_FILE "${build_log}")
if (NOT result EQUAL 0)
  fuzz_fail("Configuring the fuzz project (${CXX_COMPILER})" "${build_log}" 40)
endif ()
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
execute_process(
  COMMAND "${CMAKE_COMMAND}" --build "${build_dir}" --target ${FUZZ_TARGET} --parallel ${cores}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(APPEND "${build_log}" "${out}")
if (NOT result EQUAL 0)
  fuzz_fail("Building ${FUZZ_TARGET}" "${build_log}" 40)
endif ()
set(fuzzer "${build_dir}/${FUZZ_TARGET}")
string(TIMESTAMP built "%s")
math(EXPR build_seconds "${built} - ${start}")
message(STATUS "${FUZZ_TARGET} built in ${build_seconds} s: ${fuzzer}")

set(ENV{ASAN_OPTIONS} "abort_on_error=1:detect_leaks=1:symbolize=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
file(GLOB artifacts_before "${WORK_DIR}/crash-*" "${WORK_DIR}/timeout-*" "${WORK_DIR}/oom-*"
  "${WORK_DIR}/leak-*" "${WORK_DIR}/slow-unit-*")

# 2. Known crash inputs, each run once (libFuzzer stops at the first that fails).
set(regressions "")
if (NOT DEFINED REGRESSIONS OR REGRESSIONS)
  file(GLOB regressions LIST_DIRECTORIES false "${regression_dir}/*")
  if ("$ENV{FUZZ_FIT_EXTRA}" MATCHES "^[1-9]")
    # Inputs that fail only the stricter invariants of FUZZ_FIT_EXTRA=1.
    file(GLOB extra_regressions LIST_DIRECTORIES false "${regression_dir}/extra/*")
    list(APPEND regressions ${extra_regressions})
  endif ()
  list(FILTER regressions EXCLUDE REGEX "(/README[^/]*|\\.md|\\.txt)$")
endif ()
if (regressions)
  list(LENGTH regressions count)
  set(log "${WORK_DIR}/regressions.log")
  execute_process(COMMAND "${fuzzer}" -timeout=30 -rss_limit_mb=2048 ${regressions}
    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE result OUTPUT_FILE "${log}" ERROR_FILE "${log}")
  if (NOT result EQUAL 0)
    file(STRINGS "${log}" running REGEX "^Running: ")
    list(GET running -1 failing)
    string(REPLACE "Running: " "" failing "${failing}")
    fuzz_fail("Regression input ${failing} (exit ${result}; the first failing of ${count})"
      "${log}" 60 ${artifacts_before})
  endif ()
  message(STATUS "${FUZZ_TARGET}: ${count} regression input(s) pass")
endif ()

# 3. Fuzzing. A hang shows as an input over the per-input timeout: 30 s, not
# libFuzzer's 10, because the qqr automatic search on a short closed line can
# take 7 s in this instrumented build (0.4 s in a release build; measured on a
# 23-point line with arc-length sampling) and twice that on a loaded machine.
if (SECONDS GREATER 0)
  set(log "${WORK_DIR}/fuzz.log")
  execute_process(
    COMMAND "${fuzzer}" -max_total_time=${SECONDS} -timeout=30 -rss_limit_mb=2048
            -print_final_stats=1 ${FUZZ_ARGS} "${work_corpus}" "${seed_corpus}"
    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE result OUTPUT_FILE "${log}" ERROR_FILE "${log}")
  if (NOT result EQUAL 0)
    fuzz_fail("${FUZZ_TARGET} -max_total_time=${SECONDS} (exit ${result})" "${log}" 60 ${artifacts_before})
  endif ()
  file(STRINGS "${log}" summary REGEX "^(#[0-9]+[ \t]+DONE|Done [0-9]+ runs|stat::)")
  string(REPLACE ";" "\n  " summary "${summary}")
  message(STATUS "${FUZZ_TARGET}: no failure in ${SECONDS} s (log: ${log})\n  ${summary}")
endif ()
