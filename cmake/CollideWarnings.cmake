# collide_set_warnings(target): the project's warning set, per target (not global), so that
# generated code (the glad loader) and third-party headers are not held to it.
function(collide_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
    # GCC 12 (Debian 12's compiler) warns -Wrestrict inside libstdc++'s own string code when
    # `"literal" + std::string` is inlined at -O2 (GCC bug 105329, fixed in GCC 13): eight false
    # alarms in a Release build, none of them about this project's code.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        target_compile_options(${target} PRIVATE -Wno-restrict)
    endif()
    if(COLLIDE_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
endfunction()
