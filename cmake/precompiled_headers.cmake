# Precompiled headers (issue 22 item 5: a clean build of everything under 5 minutes on 2 cores).
# Parsing the third-party headers is a large part of most translation units: measured with g++ -O3 on
# this machine, <CLI/CLI.hpp> + <fmt/format.h> alone take 7.7 s of CPU per file, GoogleTest + Eigen +
# the field headers 3.4 s, <Eigen/Dense> 1.7 s. Each group below is parsed once per group instead.
# Only third-party and standard headers go in: no header of ours, so editing one of them never rebuilds
# more than it did, and the folder floors (scripts/check_floors) still see every include in the source.
#
# ccache caches a file compiled with a precompiled header only with sloppiness pch_defines,time_macros
# (and -fpch-preprocess for GCC); without it every such file is a cache miss. So DFVN_PCH defaults to
# OFF when the compiler launcher is ccache (the warm, cached developer build keeps hitting its cache)
# and ON otherwise (CI and a first build from a bare clone, where nothing is cached).
if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
  set(dfvn_pch_default OFF)
else()
  set(dfvn_pch_default ON)
endif()
option(DFVN_PCH "Precompile the third-party headers (GoogleTest, Eigen, fmt, CLI11, pybind11) per target group"
       ${dfvn_pch_default})

# The standard headers most of our files include.
set(DFVN_PCH_STD <algorithm> <array> <cmath> <cstdint> <cstdio> <functional> <limits> <memory> <numbers>
                 <optional> <stdexcept> <string> <string_view> <utility> <vector>)

# dfvn_precompile(<target> <group> <header>...): the first target of a group precompiles the headers,
# every later target of the same group reuses that precompiled header (same flags: same group).
function(dfvn_precompile target group)
  if(NOT DFVN_PCH)
    return()
  endif()
  get_property(owner GLOBAL PROPERTY DFVN_PCH_OWNER_${group})
  if(owner)
    target_precompile_headers(${target} REUSE_FROM ${owner})
  else()
    target_precompile_headers(${target} PRIVATE ${ARGN})
    set_property(GLOBAL PROPERTY DFVN_PCH_OWNER_${group} ${target})
  endif()
endfunction()
