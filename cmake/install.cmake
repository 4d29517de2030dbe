# What `cmake --install` puts under the prefix:
#   bin/dfvn-sample
#   bin/dfvn-sample-mpi                          only when built (-DDFVN_MPI=ON)
#   lib/libdfvn.so*                              (CMAKE_INSTALL_LIBDIR)
#   include/dfvn/dfvn.hpp, include/dfvn/<concept>/*.hpp   the public headers (an explicit list below)
#   lib/cmake/dfvn/                              find_package(dfvn) -> dfvn::dfvn
#   lib/pkgconfig/dfvn.pc                        pkg-config --cflags --libs dfvn
#   share/dfvn/                                  DFVN_DATA_DIR: the plot programs
#   share/man/man1/dfvn-sample.1                 from --help-all (every subcommand), when help2man is found
#   share/man/man1/dfvn-sample-mpi.1             from its --help, when help2man is found and it is built
#   share/bash-completion/completions/dfvn-sample (and dfvn-sample-mpi, the same file, when that is built)
# Every path is relative to the prefix, so the tree may be installed anywhere (--prefix) and moved.
include(CMakePackageConfigHelpers)

set(DFVN_DATA_DIR ${CMAKE_INSTALL_DATADIR}/dfvn CACHE STRING
    "Where the plot programs and other run-time data are installed, relative to the prefix")
set(DFVN_CMAKE_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dfvn)

# The installed binary finds the installed libdfvn relative to itself.
file(RELATIVE_PATH dfvn_bin_to_lib /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR})
set_target_properties(dfvn-sample PROPERTIES INSTALL_RPATH "$ORIGIN/${dfvn_bin_to_lib}")

install(TARGETS dfvn-sample RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET dfvn-sample-mpi)
  set_target_properties(dfvn-sample-mpi PROPERTIES INSTALL_RPATH "$ORIGIN/${dfvn_bin_to_lib}")
  install(TARGETS dfvn-sample-mpi RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(TARGETS dfvn EXPORT dfvnTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The public headers, by name: the API of src/dfvn.hpp (the umbrella <dfvn/dfvn.hpp>, which includes
# exactly these; the install test checks that). Not installed: headers of private dependencies (OpenMP,
# nanoflann), template internals (trace_impl, the turning-bands kernel, neighbour loops), the
# reproductions, the plots and the command line's text helpers. Every include is written
# "dfvn/<folder>/<file>.hpp", so a consumer adds only <prefix>/include to its include path.
set(DFVN_PUBLIC_HEADERS
    animate/animation.hpp
    core/bulk_memory.hpp
    core/dimension.hpp
    core/domain.hpp
    core/image.hpp
    core/point_set.hpp
    core/progress.hpp
    core/quantile.hpp
    core/seeds.hpp
    core/simd.hpp
    core/stopwatch.hpp
    core/torus.hpp
    core/tree_sum.hpp
    experiment/experiment.hpp
    experiment/realizations.hpp
    experiment/streamed_sampling.hpp
    field/constraint.hpp
    field/cross_product.hpp
    field/dfvn_field.hpp
    field/obstacles.hpp
    field/bridson_flow.hpp
    field/diagnose.hpp
    field/evaluate_points.hpp
    field/field_transform.hpp
    integrate/trace.hpp
    integrate/trace_points.hpp
    io/atomic_file.hpp
    io/csv.hpp
    io/field_csv.hpp
    io/png.hpp
    io/point_file.hpp
    io/point_reader.hpp
    io/point_sidecar.hpp
    io/utk_bin.hpp
    noise/gradient_noise.hpp
    noise/noise_domain.hpp
    noise/noise_functions.hpp
    noise/noise_transforms.hpp
    noise/simplex_noise.hpp
    noise/rotating_gradients.hpp
    noise/simplex_separate.hpp
    noise/steerable_noise.hpp
    noise/turning_bands.hpp
    quadrature/genz.hpp
    sampling/curl_noise_jitter.hpp
    sampling/halton.hpp
    sampling/jitter.hpp
    sampling/latin_hypercube.hpp
    sampling/lattice.hpp
    sampling/method.hpp
    sampling/poisson_disk.hpp
    sampling/sobol.hpp
    sampling/sphere_jitter.hpp
    stats/discrepancy.hpp
    stats/distance_scale.hpp
    stats/geodesic.hpp
    stats/lattice_displacement.hpp
    stats/nearest_neighbour.hpp
    stats/periodic_neighbours.hpp
    stats/point_set_statistics.hpp
    stats/radial_distribution.hpp
    stats/spectrum.hpp
    warp/image_warp.hpp)
install(FILES src/dfvn.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dfvn)
foreach(header IN LISTS DFVN_PUBLIC_HEADERS)
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES src/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dfvn/${folder})
endforeach()

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
# section) and `--version`, with the sections help2man cannot read from the help (EXIT STATUS,
# ENVIRONMENT, FILES) from cmake/dfvn-sample.h2m (the MPI runner's page: EXIT STATUS from
# cmake/exit-status.h2m), when help2man is there; without it the page is skipped with a note.
find_program(DFVN_HELP2MAN help2man)
if(DFVN_HELP2MAN)
  set(dfvn_man_page ${CMAKE_CURRENT_BINARY_DIR}/dfvn-sample.1)
  add_custom_command(
    OUTPUT ${dfvn_man_page}
    COMMAND ${DFVN_HELP2MAN} --no-info --no-discard-stderr --help-option=--help-all
            "--name=divergence-free vector noise, curl-noise jittering and point-set statistics"
            --include=${CMAKE_CURRENT_SOURCE_DIR}/cmake/dfvn-sample.h2m
            --output=${dfvn_man_page} $<TARGET_FILE:dfvn-sample>
    DEPENDS dfvn-sample ${CMAKE_CURRENT_SOURCE_DIR}/cmake/dfvn-sample.h2m
    COMMENT "Generating the man page dfvn-sample.1 with help2man")
  add_custom_target(dfvn-sample-man ALL DEPENDS ${dfvn_man_page})
  install(FILES ${dfvn_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  if(TARGET dfvn-sample-mpi)  # its own page, from its --help
    set(dfvn_mpi_man_page ${CMAKE_CURRENT_BINARY_DIR}/dfvn-sample-mpi.1)
    add_custom_command(
      OUTPUT ${dfvn_mpi_man_page}
      COMMAND ${DFVN_HELP2MAN} --no-info --no-discard-stderr --include=${PROJECT_SOURCE_DIR}/cmake/exit-status.h2m
              "--name=dfvn-sample sample --stream over MPI ranks, with the one-process bytes"
              --output=${dfvn_mpi_man_page} $<TARGET_FILE:dfvn-sample-mpi>
      DEPENDS dfvn-sample-mpi ${PROJECT_SOURCE_DIR}/cmake/exit-status.h2m
      COMMENT "Generating the man page dfvn-sample-mpi.1 with help2man")
    add_custom_target(dfvn-sample-mpi-man ALL DEPENDS ${dfvn_mpi_man_page})
    install(FILES ${dfvn_mpi_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  endif()
else()
  message(STATUS "help2man not found: no man page (apt-get install help2man)")
endif()

install(FILES scripts/dfvn-sample-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME dfvn-sample)
if(TARGET dfvn-sample-mpi)
  install(FILES scripts/dfvn-sample-completion.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
          RENAME dfvn-sample-mpi)
endif()
