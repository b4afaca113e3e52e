# The arrows between the modules that must never exist (issue #27), checked when the build is
# configured: a target that links one of its forbidden targets, directly or through the libraries
# it links, stops the configuration.
#   collide_check_arrows(TARGET FORBIDDEN...)

# All targets `target` links, directly or transitively (PUBLIC/INTERFACE and PRIVATE of static
# libraries alike: a static library's private links end up in every executable that uses it).
function(_collide_linked_targets target out)
    set(seen ${${out}})
    set(libs "")
    get_target_property(type ${target} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(direct ${target} LINK_LIBRARIES)
        if(direct)
            list(APPEND libs ${direct})
        endif()
    endif()
    get_target_property(iface ${target} INTERFACE_LINK_LIBRARIES)
    if(iface)
        list(APPEND libs ${iface})
    endif()
    foreach(lib IN LISTS libs)
        # $<LINK_ONLY:x> and other generator expressions around a name: keep the name.
        string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" lib "${lib}")
        if(TARGET ${lib} AND NOT lib IN_LIST seen)
            list(APPEND seen ${lib})
            _collide_linked_targets(${lib} seen)
        endif()
    endforeach()
    set(${out} ${seen} PARENT_SCOPE)
endfunction()

function(collide_check_arrows target)
    if(NOT TARGET ${target})
        return()
    endif()
    set(linked "")
    _collide_linked_targets(${target} linked)
    foreach(forbidden IN LISTS ARGN)
        if(forbidden IN_LIST linked)
            message(FATAL_ERROR "collide: ${target} must not link ${forbidden}: an arrow between "
                                "modules that must never exist (issue #27)")
        endif()
    endforeach()
endfunction()
