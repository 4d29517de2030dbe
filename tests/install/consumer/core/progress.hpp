// The consumer's own core/progress.hpp, named like one of libdfvn's headers on purpose: the installed headers
// include each other as "dfvn/<folder>/<file>.hpp", so none of them may ever resolve to this file
// (it would stop the build), while main.cpp includes it on purpose after the library's headers.
#pragma once
#ifndef CONSUMER_OWN_HEADERS
#error "a dfvn header included the consumer's own core/progress.hpp instead of its own"
#endif
inline constexpr const char* consumer_core_progress = "core/progress";
