# parcelflow_add_gtest(NAME SOURCES src... LIBS lib... LABELS label... [RANKS n...])
# One GoogleTest executable; one CTest entry per rank count (run through mpirun when RANKS is given).
# Labels: unit, regression, validation, benchmark (the default `ctest` run excludes benchmark).
include_guard(GLOBAL)

# Open MPI refuses to run as root and to place more ranks than cores unless told; CI runs as root on
# 2 cores and the tests use up to 3 ranks.
set(PARCELFLOW_MPIEXEC_FLAGS --oversubscribe)
execute_process(COMMAND id -u OUTPUT_VARIABLE _parcelflow_uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(_parcelflow_uid STREQUAL "0")
  list(APPEND PARCELFLOW_MPIEXEC_FLAGS --allow-run-as-root)
endif()

function(parcelflow_add_gtest name)
  cmake_parse_arguments(T "" "TIMEOUT" "SOURCES;LIBS;LABELS;RANKS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest)
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 600)
  endif()
  if(NOT T_RANKS)
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT})
    return()
  endif()
  foreach(n IN LISTS T_RANKS)
    add_test(NAME ${name}_np${n}
             COMMAND ${MPIEXEC_EXECUTABLE} ${PARCELFLOW_MPIEXEC_FLAGS} -np ${n} $<TARGET_FILE:${name}>)
    set_tests_properties(${name}_np${n} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
                         PROCESSORS ${n})
  endforeach()
endfunction()

# parcelflow_add_python_benchmark(NAME SCRIPT [extra script arguments...])
# A Python benchmark, run alone on 1 and then 2 ranks (NAME_np1, NAME_np2; label benchmark). The script
# gets --parcelflow BIN, the extra arguments, --ranks N and last --mpiexec MPIEXEC FLAGS...
function(parcelflow_add_python_benchmark name script)
  foreach(ranks 1 2)
    add_test(NAME ${name}_np${ranks}
             COMMAND ${PARCELFLOW_PYTHON} ${script} --parcelflow $<TARGET_FILE:parcelflow> ${ARGN} --ranks ${ranks}
                     --mpiexec ${MPIEXEC_EXECUTABLE} ${PARCELFLOW_MPIEXEC_FLAGS})
    set_tests_properties(${name}_np${ranks} PROPERTIES LABELS benchmark TIMEOUT 3600 PROCESSORS ${ranks}
                         RUN_SERIAL TRUE)
  endforeach()
endfunction()
