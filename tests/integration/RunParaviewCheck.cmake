# CTest driver for the ParaView check (cmake -P): the helper writes the sample outputs,
# then pvpython checks them. Never passes without running pvpython.
if(NOT PVPYTHON)
  message(FATAL_ERROR "pvpython not found: install python3-paraview (then re-run cmake)")
endif()
execute_process(COMMAND ${HELPER} ${OUTPUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "write_sample_outputs failed (${rc})")
endif()
execute_process(COMMAND ${PVPYTHON} ${SCRIPT} ${OUTPUT}/expected.json RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "paraview_check.py failed (${rc})")
endif()
