# What `cmake --install` puts under the prefix:
#   bin/dfvn-sample
#   lib/libdfvn.so*                              (CMAKE_INSTALL_LIBDIR)
#   include/dfvn/<concept>/*.hpp                 the library's public headers, in the source layout
#   lib/cmake/dfvn/                              find_package(dfvn) -> dfvn::dfvn
#   lib/pkgconfig/dfvn.pc                        pkg-config --cflags --libs dfvn
#   share/dfvn/                                  DFVN_DATA_DIR: the plot programs
#   share/man/man1/dfvn-sample.1                 from --help-all (every subcommand), when help2man is found
#   share/bash-completion/completions/dfvn-sample
# Every path is relative to the prefix, so the tree may be installed anywhere (--prefix) and moved.
include(CMakePackageConfigHelpers)

set(DFVN_DATA_DIR ${CMAKE_INSTALL_DATADIR}/dfvn CACHE STRING
    "Where the plot programs and other run-time data are installed, relative to the prefix")
set(DFVN_CMAKE_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dfvn)

# The installed binary finds the installed libdfvn relative to itself.
file(RELATIVE_PATH dfvn_bin_to_lib /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR})
set_target_properties(dfvn-sample PROPERTIES INSTALL_RPATH "$ORIGIN/${dfvn_bin_to_lib}")

install(TARGETS dfvn-sample RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS dfvn EXPORT dfvnTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The public headers: everything in src/ except those that exist only for the library's own
# translation units and pull in private dependencies (OpenMP, nanoflann) or template internals.
install(DIRECTORY src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dfvn
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "parallel.hpp" EXCLUDE
        PATTERN "kd_tree.hpp" EXCLUDE
        PATTERN "trace_impl.hpp" EXCLUDE
        PATTERN "turning_bands_kernel.hpp" EXCLUDE
        PATTERN "periodic_images.hpp" EXCLUDE
        PATTERN "neighbour_loop.hpp" EXCLUDE
        REGEX "integrate/trace_table.hpp" EXCLUDE)

install(EXPORT dfvnTargets NAMESPACE dfvn:: DESTINATION ${DFVN_CMAKE_PACKAGE_DIR})
configure_package_config_file(cmake/dfvnConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/dfvnConfig.cmake
                              INSTALL_DESTINATION ${DFVN_CMAKE_PACKAGE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/dfvnConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/dfvnConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/dfvnConfigVersion.cmake
        DESTINATION ${DFVN_CMAKE_PACKAGE_DIR})

# pkg-config: the prefix is found from the .pc file's own place (${pcfiledir}), so it stays right
# after `cmake --install --prefix` or a move.
file(RELATIVE_PATH dfvn_pc_to_prefix /${CMAKE_INSTALL_LIBDIR}/pkgconfig /)
string(REGEX REPLACE "/$" "" dfvn_pc_to_prefix "${dfvn_pc_to_prefix}")
configure_file(cmake/dfvn.pc.in ${CMAKE_CURRENT_BINARY_DIR}/dfvn.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/dfvn.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# The gnuplot programs that draw the figures (the binary has them compiled in; installed for users who
# redraw a figure from its CSV: gnuplot -c figure4.gp ...).
file(GLOB dfvn_plot_programs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/scripts/*.gp)
install(FILES ${dfvn_plot_programs} DESTINATION ${DFVN_DATA_DIR})

# The man page, from `dfvn-sample --help-all` (the help of every subcommand, reproduce's included, each a
# section) and `--version`, when help2man is there; without it the page is skipped with a note.
find_program(DFVN_HELP2MAN help2man)
if(DFVN_HELP2MAN)
  set(dfvn_man_page ${CMAKE_CURRENT_BINARY_DIR}/dfvn-sample.1)
  add_custom_command(
    OUTPUT ${dfvn_man_page}
    COMMAND ${DFVN_HELP2MAN} --no-info --no-discard-stderr --help-option=--help-all
            "--name=divergence-free vector noise, curl-noise jittering and point-set statistics"
            --output=${dfvn_man_page} $<TARGET_FILE:dfvn-sample>
    DEPENDS dfvn-sample
    COMMENT "Generating the man page dfvn-sample.1 with help2man")
  add_custom_target(dfvn-sample-man ALL DEPENDS ${dfvn_man_page})
  install(FILES ${dfvn_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (apt-get install help2man)")
endif()

install(FILES scripts/dfvn-sample-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME dfvn-sample)
