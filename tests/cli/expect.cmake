# Runs one command and checks its exit code and output. Used by cli_tests.cmake:
#   cmake -DEXE=<program> -DARGS="a|b|c" -DEXPECT_CODE=2
#         [-DEXPECT_STDERR=<regex>] [-DEXPECT_STDOUT=<regex>] [-DEXPECT_FILES="f1|f2"]
#         [-DKEEP_FILE=<path>] -P expect.cmake
# KEEP_FILE is written before the command and must hold the same text after it (a refused run
# leaves an earlier result alone).
# ARGS and EXPECT_FILES use "|" between items, since ";" does not survive add_test.
if(NOT DEFINED EXE OR NOT DEFINED EXPECT_CODE)
  message(FATAL_ERROR "expect.cmake needs -DEXE and -DEXPECT_CODE")
endif()
string(REPLACE "|" ";" _args "${ARGS}")
if(DEFINED EXPECT_FILES)
  string(REPLACE "|" ";" _files "${EXPECT_FILES}")
  foreach(_f IN LISTS _files)
    file(REMOVE "${_f}")
  endforeach()
endif()

if(DEFINED KEEP_FILE)
  file(WRITE "${KEEP_FILE}" "an earlier result\n")
endif()

execute_process(COMMAND "${EXE}" ${_args}
  RESULT_VARIABLE _code OUTPUT_VARIABLE _out ERROR_VARIABLE _err)

set(_failed "")
if(NOT "${_code}" STREQUAL "${EXPECT_CODE}")
  string(APPEND _failed "exit code ${_code}, expected ${EXPECT_CODE}\n")
endif()
if(DEFINED EXPECT_STDERR AND NOT _err MATCHES "${EXPECT_STDERR}")
  string(APPEND _failed "stderr does not match '${EXPECT_STDERR}'\n")
endif()
if(DEFINED EXPECT_STDOUT AND NOT _out MATCHES "${EXPECT_STDOUT}")
  string(APPEND _failed "stdout does not match '${EXPECT_STDOUT}'\n")
endif()
foreach(_f IN LISTS _files)
  if(NOT EXISTS "${_f}")
    string(APPEND _failed "expected file ${_f} was not written\n")
  endif()
endforeach()

if(DEFINED KEEP_FILE)
  file(READ "${KEEP_FILE}" _kept)
  if(NOT _kept STREQUAL "an earlier result\n")
    string(APPEND _failed "${KEEP_FILE} was changed by a refused run\n")
  endif()
endif()

if(_failed)
  string(SUBSTRING "${_out}" 0 2000 _out_head)
  message(FATAL_ERROR "${EXE} ${_args}\n${_failed}--- stdout (first 2000 chars):\n${_out_head}\n"
                      "--- stderr:\n${_err}")
endif()
