# cmake -DPROGRAM=collide-draw -DOUT=DIR -P GenerateDocs.cmake: the man page and the bash, zsh and
# fish completion, as the program's own command line describes them (src/app/cli_docs.cpp), and
# the man page compressed for installation (gzip -9n: the same bytes every build).
foreach(pair "man;collide.1" "bash;collide.bash" "zsh;_collide" "fish;collide.fish")
    list(GET pair 0 kind)
    list(GET pair 1 file)
    execute_process(COMMAND ${PROGRAM} --generate-docs ${kind} OUTPUT_FILE ${OUT}/${file}.tmp
                    RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "${PROGRAM} --generate-docs ${kind} failed: ${result}")
    endif()
    file(RENAME ${OUT}/${file}.tmp ${OUT}/${file})
endforeach()
execute_process(COMMAND gzip -9 -n -c ${OUT}/collide.1 OUTPUT_FILE ${OUT}/collide.1.gz
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "gzip of the man page failed: ${result}")
endif()
