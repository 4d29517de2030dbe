// The consumer's own core/point_set.hpp, named like one of libdfvn's headers on purpose: the installed headers
// include each other as "dfvn/<folder>/<file>.hpp", so none of them may ever resolve to this file
// (it would stop the build), while main.cpp includes it on purpose after the library's headers.
#pragma once
#ifndef CONSUMER_OWN_HEADERS
#error "a dfvn header included the consumer's own core/point_set.hpp instead of its own"
#endif
inline constexpr const char* consumer_core_point_set = "core/point_set";
