# Installation and the Debian package (docs/install.md): `cmake --install BUILD --prefix P`
# and `cpack` in the build folder. The layout is Debian's, and the program finds each part
# relative to its own folder (src/core/program_folder.h), so any prefix works unmoved.
include(GNUInstallDirs)

# `cmake --install` and cpack take what is built rather than building everything first (the
# tests and benchmarks too): build veduta, veduta-diff, veduta-images and veduta_help_files,
# or all, before them.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

# The program looks for ../lib/veduta and ../share/veduta beside its own folder, fixed in the
# code: an installation with other folder names would not find its parts.
if(NOT CMAKE_INSTALL_BINDIR STREQUAL "bin" OR NOT CMAKE_INSTALL_DATADIR STREQUAL "share")
  message(FATAL_ERROR "veduta finds its parts in ../lib/veduta and ../share/veduta beside its bin/ "
                      "(src/core/program_folder.h): leave CMAKE_INSTALL_BINDIR at bin and CMAKE_INSTALL_DATADIR at share")
endif()
# Not CMAKE_INSTALL_LIBDIR: that is lib/<triplet> for the prefix /usr, and the plugin and
# veduta-diff are veduta's private parts, not libraries for others (FHS 4.6: an application
# may use one folder under /usr/lib for its object files and internal binaries; git uses
# /usr/lib/git-core alike).
set(VEDUTA_INSTALL_PRIVATEDIR lib/veduta)
set(VEDUTA_INSTALL_DATAROOT ${CMAKE_INSTALL_DATADIR}/veduta)

install(TARGETS veduta RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS veduta-diff RUNTIME DESTINATION ${VEDUTA_INSTALL_PRIVATEDIR})
# Read and mapped, never executed: without the execute bits Debian wants on shared objects.
install(TARGETS veduta-images LIBRARY DESTINATION ${VEDUTA_INSTALL_PRIVATEDIR}
        PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)

# What the program and the example scenes read: rules/ (veduta generate, twin and every
# building scene), materials/ and environments/ (scenes/materials.xml, the palace), cities/ and
# data/ (the city and landscape scenes). The Python scripts that made some of the data are
# not needed to use it.
install(DIRECTORY rules materials environments scenes cities data
        DESTINATION ${VEDUTA_INSTALL_DATAROOT} PATTERN "*.py" EXCLUDE)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
# As in the checkout, docs/ beside README.md, so that README's links hold.
install(DIRECTORY docs DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The man page and the bash completion are written from the built program's --help
# (packaging/), so they change when its options do. Leak checks off: a sanitizer build runs
# the instrumented program here, and OpenImageIO (veduta diff --help) keeps allocations to exit.
set(VEDUTA_HELP_DIR ${PROJECT_BINARY_DIR}/packaging)
set(VEDUTA_MANPAGE ${VEDUTA_HELP_DIR}/veduta.1.gz)
set(VEDUTA_COMPLETION ${VEDUTA_HELP_DIR}/veduta.bash)
set(VEDUTA_HELP_SCRIPTS ${PROJECT_SOURCE_DIR}/packaging/help_lib.sh)
add_custom_command(
  OUTPUT ${VEDUTA_MANPAGE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${VEDUTA_HELP_DIR}
  COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0 bash ${PROJECT_SOURCE_DIR}/packaging/make_manpage.sh
          $<TARGET_FILE:veduta> ${PROJECT_VERSION} ${VEDUTA_MANPAGE}
  DEPENDS veduta veduta-diff ${PROJECT_SOURCE_DIR}/packaging/make_manpage.sh ${VEDUTA_HELP_SCRIPTS}
  COMMENT "Writing the man page veduta.1 from veduta's --help"
  VERBATIM)
add_custom_command(
  OUTPUT ${VEDUTA_COMPLETION}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${VEDUTA_HELP_DIR}
  COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0 bash ${PROJECT_SOURCE_DIR}/packaging/make_completion.sh
          $<TARGET_FILE:veduta> ${VEDUTA_COMPLETION}
  DEPENDS veduta veduta-diff ${PROJECT_SOURCE_DIR}/packaging/make_completion.sh ${VEDUTA_HELP_SCRIPTS}
  COMMENT "Writing the bash completion of veduta from its --help"
  VERBATIM)
add_custom_target(veduta_help_files ALL DEPENDS ${VEDUTA_MANPAGE} ${VEDUTA_COMPLETION})
install(FILES ${VEDUTA_MANPAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${VEDUTA_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME veduta)

# `cpack` in the build folder: veduta_<version>_amd64.deb. dpkg-shlibdeps (dpkg-dev) finds the
# libraries' packages; proj-data is read, not linked: PROJ opens BETA2007.gsb, the DHDN grid
# of the Gauss-Krüger conversions, from /usr/share/proj.
set(VEDUTA_PACKAGE_MAINTAINER "veduta maintainers <maintainers@users.noreply.h-seed-ddac9c3e.example>"
    CACHE STRING "The Maintainer field of the Debian package")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME veduta)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "offline path tracer for German landscape and city stills")
string(CONCAT CPACK_DEBIAN_PACKAGE_DESCRIPTION
       "veduta reads a scene description, builds its geometry (terrain from DGM and ATKIS data,\n"
       "procedural streets, lots, buildings and facades, meshes and instances), and path-traces it\n"
       "to multilayer OpenEXR, with display images through OpenColorIO.")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${VEDUTA_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS proj-data)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
