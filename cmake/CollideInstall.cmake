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
install(FILES ${PROJECT_SOURCE_DIR}/docs/collide.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/completion/collide.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME collide)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The data directory relative to the program, as data_dir() looks for it.
file(RELATIVE_PATH collide_data_from_bin "/prefix/${CMAKE_INSTALL_BINDIR}"
     "/prefix/${CMAKE_INSTALL_DATADIR}/collide")
if(NOT collide_data_from_bin STREQUAL "../share/collide")
    message(FATAL_ERROR "collide finds its data at ../share/collide from its bin directory; "
                        "CMAKE_INSTALL_BINDIR/DATADIR give ${collide_data_from_bin}")
endif()

# A .deb: `cpack -G DEB --config BUILD/CPackConfig.cmake` (docs/install.md). Its dependencies
# come from the libraries the program links (dpkg-shlibdeps), not from a list kept by hand.
set(CPACK_PACKAGE_NAME collide)
set(CPACK_PACKAGE_VENDOR "collide")
set(CPACK_PACKAGE_CONTACT "collide maintainers <collide@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The text needs a font (the search of docs/install.md starts with DejaVu Sans).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fontconfig")
include(CPack)
