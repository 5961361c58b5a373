# run(COMMAND...): runs a command and stops the script with its exit status
# and words when it fails (for the cmake -P test scripts here).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}")
  endif ()
endfunction()
