# Run after a test binary is built (tests/CMakeLists.txt, igds_test_binary): writes OUT, the
# CTest file that makes each of its doctest cases a test, labelled with LABEL (the binary's folder)
# and, when the case is in the doctest suite "slow", with "slow" too. Two runs of the binary list
# them all; asking each case for its suites would run it once a case.
#   cmake -D EXE=... -D LABEL=... -D DIR=... -D TIMEOUT=... -D SLOW_TIMEOUT=... -D OUT=... -P this
cmake_minimum_required(VERSION 3.25)

function(case_names out)
  execute_process(COMMAND "${EXE}" --list-test-cases ${ARGN} OUTPUT_VARIABLE listed
                  RESULT_VARIABLE status WORKING_DIRECTORY "${DIR}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${EXE} --list-test-cases ${ARGN}: status ${status}\n${listed}")
  endif()
  # A semicolon in a name would cut it in two as a CMake list: kept as a mark until the name is
  # written (as a comma in the test's name, and doctest's one-character wildcard in its filter).
  string(REPLACE ";" "<semicolon>" listed "${listed}")
  string(REPLACE "\n" ";" lines "${listed}")
  set(names)
  foreach(line IN LISTS lines)
    # doctest frames the names with a rule and [doctest] lines.
    if(line STREQUAL "" OR line MATCHES "^===+$" OR line MATCHES "^\\[doctest\\] ")
      continue()
    endif()
    list(APPEND names "${line}")
  endforeach()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

case_names(all)
case_names(slow --test-suite=slow)

set(script "")
foreach(name IN LISTS all)
  set(labels "${LABEL}")
  set(timeout ${TIMEOUT})
  set(cost 0)
  if(name IN_LIST slow)
    list(APPEND labels slow)
    set(timeout ${SLOW_TIMEOUT})
    # Started first, so that a long case does not end the run alone on one core.
    set(cost 1000)
  endif()
  # A comma separates doctest's filters: one in a name is escaped.
  string(REPLACE "," "\\," filter "${name}")
  string(REPLACE "<semicolon>" "?" filter "${filter}")
  string(REPLACE "<semicolon>" "," name "${name}")
  string(APPEND script
         "add_test([==[${name}]==] [==[${EXE}]==] [==[--test-case=${filter}]==])\n"
         "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${DIR}]==]"
         " LABELS [==[${labels}]==] TIMEOUT ${timeout} COST ${cost} SKIP_RETURN_CODE 77"
         " ENVIRONMENT IGDS_UNDER_CTEST=1)\n")
endforeach()
file(WRITE "${OUT}" "${script}")
