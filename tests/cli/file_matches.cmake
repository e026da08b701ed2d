# Checks that a file's text matches a regex. Used by cli_tests.cmake:
#   cmake -DFILE=<path> -DPATTERN=<regex> -P file_matches.cmake
file(READ "${FILE}" _text)
if(NOT _text MATCHES "${PATTERN}")
  message(FATAL_ERROR "${FILE} does not match '${PATTERN}'")
endif()
