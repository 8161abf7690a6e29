# Without a display, sylva-studio must say so in one line that points to the CLI, and exit
# non-zero. cmake -DSTUDIO=... -P this
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY "${STUDIO}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 20)
if(result EQUAL 0)
  message(FATAL_ERROR "sylva-studio without a display exited 0")
endif()
string(STRIP "${err}" message)
if(NOT message MATCHES "display" OR NOT message MATCHES "sylva export")
  message(FATAL_ERROR "expected a message about the display pointing to `sylva export`, got: ${err}")
endif()
if(message MATCHES "\n")
  message(FATAL_ERROR "expected one line, got: ${err}")
endif()
