# collide_forbid_links(target FORBIDDEN name...): fails the configure step when `target` links,
# directly or through any library it links (PUBLIC, PRIVATE or INTERFACE), a library whose name
# matches one of the FORBIDDEN regular expressions. The arrows between modules are part of the
# build: a presentation layer that reached for GL or the CLI stops the build here instead of in
# review. Call it once every target is defined (at the end of the top-level CMakeLists.txt).
function(_collide_link_closure target out_var)
    set(seen "")
    set(todo "${target}")
    while(todo)
        list(POP_FRONT todo item)
        # $<LINK_ONLY:x> and other simple wrappers: keep the name inside.
        string(REGEX REPLACE "^\\$<[A-Z_]+:(.*)>$" "\\1" item "${item}")
        if(item STREQUAL "" OR item IN_LIST seen)
            continue()
        endif()
        list(APPEND seen "${item}")
        if(TARGET "${item}")
            get_target_property(aliased "${item}" ALIASED_TARGET)
            if(aliased)
                list(APPEND todo "${aliased}")
            endif()
            foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
                get_target_property(links "${item}" ${property})
                if(links)
                    list(APPEND todo ${links})
                endif()
            endforeach()
        endif()
    endwhile()
    set(${out_var} "${seen}" PARENT_SCOPE)
endfunction()

function(collide_forbid_links target)
    cmake_parse_arguments(ARG "" "" "FORBIDDEN" ${ARGN})
    _collide_link_closure(${target} closure)
    foreach(item IN LISTS closure)
        foreach(pattern IN LISTS ARG_FORBIDDEN)
            if(item MATCHES "${pattern}")
                message(FATAL_ERROR "${target} must not link ${item} (it matches '${pattern}'); "
                                    "see the target's CMakeLists.txt")
            endif()
        endforeach()
    endforeach()
endfunction()
