# `cmake --install BUILD --prefix PREFIX` (docs/install.md): the program, its data, a man page and
# bash completion. The program finds PREFIX/share/collide next to itself (../share/collide from
# PREFIX/bin, through /proc/self/exe), so a prefix can be moved or packaged as it is.
include(GNUInstallDirs)

install(TARGETS collide RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The drawing commands' program, which `collide` execs (src/app/CMakeLists.txt).
install(TARGETS collide-draw RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/collide)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/scenes
        DESTINATION ${CMAKE_INSTALL_DATADIR}/collide
        FILES_MATCHING PATTERN "*.toml")

# The man page and the bash, zsh and fish completion are generated from the command line itself
# (collide-draw --generate-docs, src/app/cli_docs.cpp) each time the program is built, so they
# name every command and option there is (tests/app/test_cli_docs.cpp checks it).
set(collide_docs_dir ${PROJECT_BINARY_DIR}/generated/docs)
set(collide_docs ${collide_docs_dir}/collide.1 ${collide_docs_dir}/collide.1.gz
    ${collide_docs_dir}/collide.bash ${collide_docs_dir}/_collide ${collide_docs_dir}/collide.fish)
add_custom_command(OUTPUT ${collide_docs}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${collide_docs_dir}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:collide-draw> -DOUT=${collide_docs_dir}
            -P ${PROJECT_SOURCE_DIR}/cmake/GenerateDocs.cmake
    DEPENDS collide-draw ${PROJECT_SOURCE_DIR}/cmake/GenerateDocs.cmake
    COMMENT "Generating the man page and the shell completion from the command line"
    VERBATIM)
add_custom_target(collide_docs ALL DEPENDS ${collide_docs})
install(FILES ${collide_docs_dir}/collide.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${collide_docs_dir}/collide.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME collide)
install(FILES ${collide_docs_dir}/_collide
        DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
install(FILES ${collide_docs_dir}/collide.fish
        DESTINATION ${CMAKE_INSTALL_DATADIR}/fish/vendor_completions.d)

# What a package's documentation directory holds (Debian policy, checked by lintian): the
# copyright in the machine-readable format (DEP-5; the GPL itself is in /usr/share/common-licenses)
# and the Debian changelog, compressed.
set(COLLIDE_PACKAGE_MAINTAINER "collide maintainers <collide@example.org>" CACHE STRING
    "The Maintainer of the .deb (name <address>): set it to the department's packager")
set(COLLIDE_DEB_REVISION 1 CACHE STRING "The Debian revision of the .deb (version 0.1.0-REVISION)")
set(COLLIDE_DEB_VERSION "${PROJECT_VERSION}-${COLLIDE_DEB_REVISION}")
configure_file(${PROJECT_SOURCE_DIR}/packaging/debian/copyright ${collide_docs_dir}/copyright @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/packaging/debian/changelog ${collide_docs_dir}/changelog.Debian
               @ONLY)
execute_process(COMMAND gzip -9 -n -c ${collide_docs_dir}/changelog.Debian
                OUTPUT_FILE ${collide_docs_dir}/changelog.Debian.gz COMMAND_ERROR_IS_FATAL ANY)
install(FILES ${collide_docs_dir}/copyright ${collide_docs_dir}/changelog.Debian.gz
              ${PROJECT_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
# A package outside Debian has no Intent To Package bug for its first changelog entry to close.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/lintian-overrides
        DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME collide)

# The data directory relative to the program, as data_dir() looks for it.
file(RELATIVE_PATH collide_data_from_bin "/prefix/${CMAKE_INSTALL_BINDIR}"
     "/prefix/${CMAKE_INSTALL_DATADIR}/collide")
if(NOT collide_data_from_bin STREQUAL "../share/collide")
    message(FATAL_ERROR "collide finds its data at ../share/collide from its bin directory; "
                        "CMAKE_INSTALL_BINDIR/DATADIR give ${collide_data_from_bin}")
endif()

# A .deb: `cpack -G DEB --config BUILD/CPackConfig.cmake` from a Release build (docs/install.md).
# Its dependencies come from the libraries the program links (dpkg-shlibdeps), not from a list
# kept by hand. `lintian` on it prints nothing (tests/install/deb_test.sh).
set(CPACK_PACKAGE_NAME collide)
set(CPACK_PACKAGE_VENDOR "collide")
set(CPACK_PACKAGE_CONTACT "${COLLIDE_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${COLLIDE_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "teaching videos of event-driven hard-disc simulation")
# The long description, in lines that fit 80 columns (lintian: extended-description-line-too-long;
# CPack does not wrap them).
set(CPACK_PACKAGE_DESCRIPTION
    "collide simulates hard discs bouncing elastically in a box two ways, side by
side: event-driven (a priority queue of predicted collisions) and time-driven
(fixed steps, overlaps checked), and draws both with OpenGL offscreen into MP4,
GIF or PNG files, with captions, subtitles and chapters, for lectures on
event-driven simulation.

It also animates priority queues (binary, d-ary and indexed heaps) and BFS
against A* on the sliding puzzle, renders single frames for READMEs, and
compares PNG images for golden-image checks in continuous integration.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_DEBIAN_PACKAGE_RELEASE ${COLLIDE_DEB_REVISION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Binaries stripped in the package (lintian: unstripped-binary-or-object); the build tree keeps
# its debug information.
set(CPACK_STRIP_FILES ON)
# The text needs a font (the search of docs/install.md starts with DejaVu Sans); Chinese,
# Japanese and Korean come from a fallback font (Droid Sans Fallback), drawn as '?' without it.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fontconfig, fonts-droid-fallback")
include(CPack)
