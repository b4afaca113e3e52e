# collide_set_warnings(target): the project's warning set, per target (not global), so that
# generated code (the glad loader) and third-party headers are not held to it.
function(collide_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
    if(COLLIDE_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()
