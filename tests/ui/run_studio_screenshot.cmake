# Runs sylva-studio under a virtual X server, saves a screenshot and checks it.
# cmake -DSTUDIO=... -DCHECKER=... -DOUTPUT=....png -DWIDTH=1280 -DHEIGHT=800
#       [-DARGS=arg|arg...] [-DCHECK=OFF] -P this
# CHECK=OFF only requires the PNG: for frames without meshes (the colonization replay draws
# the skeleton's lines alone, too thin for the checker's tree-pixel count).
# Any failure ends in FATAL_ERROR, which makes cmake -P (and so the test) exit non-zero.
foreach(var STUDIO CHECKER OUTPUT WIDTH HEIGHT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_studio_screenshot.cmake: -D${var}=... is required")
  endif()
endforeach()

find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR
    "xvfb-run not found: the studio screenshot test needs a virtual X server "
    "(Debian: apt-get install xvfb)")
endif()

set(studio_args "")
if(DEFINED ARGS AND NOT ARGS STREQUAL "")
  string(REPLACE "|" ";" studio_args "${ARGS}")
endif()

file(REMOVE "${OUTPUT}")
# -a picks a free display number; 24-bit depth for GLX.
execute_process(
  COMMAND "${XVFB_RUN}" -a -s "-screen 0 1600x1200x24"
          "${STUDIO}" ${studio_args} --screenshot "${OUTPUT}" --frames 5
  RESULT_VARIABLE studio_result
  TIMEOUT 120)
if(NOT studio_result EQUAL 0)
  message(FATAL_ERROR "sylva-studio ${studio_args} --screenshot failed: ${studio_result}")
endif()
if(NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "sylva-studio exited 0 but wrote no ${OUTPUT}")
endif()

if(DEFINED CHECK AND NOT CHECK)
  return()
endif()
execute_process(
  COMMAND "${CHECKER}" "${OUTPUT}" ${WIDTH} ${HEIGHT}
  RESULT_VARIABLE check_result)
if(NOT check_result EQUAL 0)
  message(FATAL_ERROR "screenshot check failed for ${OUTPUT}")
endif()
