# web.page_check_fails_without_wasm: a copy of the site without wobble.wasm must fail
# page_check.py's comparison (it shows "Wobble could not start" instead of the scene).
file(REMOVE_RECURSE "${BROKEN}")
file(COPY "${SITE}/" DESTINATION "${BROKEN}")
file(REMOVE "${BROKEN}/wobble.wasm")
execute_process(COMMAND "${PYTHON}" "${CHECK}" "${BROKEN}" "${GOLDEN}" --expect-mismatch
                        --out "${BROKEN}_shot" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "page_check.py did not report the site without wobble.wasm as broken")
endif()
