#pragma once
// Key-framing a phoneme timeline into tongue shapes with look-ahead coarticulation
// (seed App. D §5, §7-8; docs/softobj.md §5): key-frames are skeleton parameters, not
// meshes, so every frame is polygonised anew.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "softobj/tongue.hpp"

namespace fest::softobj {

struct PhonemeSpec {
  bool vowel = false;
  bool deformable = false;
  std::optional<TongueParams> tongue;  // empty: the tongue is not involved (/p b m f v/)
};

struct PhonemeTable {
  std::map<std::string, PhonemeSpec> phonemes;
  double max_speed_length = 150;  // mm/s, origin and lengths
  double max_speed_angle = 600;   // deg/s (not limited: curvature keeps its shape)
  double lag_tip = 0, lag_middle = 0.01, lag_back = 0.02;  // s
};

struct TimedPhoneme {
  std::string name;
  double start = 0, end = 0;
};

struct KeyFrame {
  double time = 0;
  TongueParams params;
};

// Codecs. The table: {"phonemes": {"i": {"class": "vowel", "deformable": false,
// "tongue": {"a1": 38, ...} | null}, ...}, "max_speed": {"length": 150, "angle": 600},
// "lag_s": {"tip": 0, "middle": 0.01, "back": 0.02}}; tongue members not given keep the
// neutral shape. The timeline: lines "phoneme start_s end_s [stress]", whitespace
// separated, '#' comments. Both throw fest::Error(bad_input) naming the line or member.
PhonemeTable decode_phoneme_table(std::string_view text);
std::vector<TimedPhoneme> decode_timeline(std::string_view text, const PhonemeTable& table);

// Rules 1-4 of docs/softobj.md §5: a key at each phoneme's midpoint; a phoneme without
// a target anticipates the next target from its own start; deformable phonemes blend
// half-way with their neighbours; origin and lengths undershoot when reaching a target
// needs more than the maximum speed (angles do not).
std::vector<KeyFrame> key_frames(const std::vector<TimedPhoneme>& timeline, const PhonemeTable& table);

// Rules 5-6: parameters at time t by Catmull-Rom (finite-difference Hermite) interpolation
// of the keys, each sagittal row delayed by its lag (tip: x0 y0 z0 l1 l4 l5 a1 c1 c2;
// middle: l2 l6 l7 a2 c3 c4; back: l3 l8 l9 a3 c5 c6).
TongueParams params_at(const std::vector<KeyFrame>& keys, const PhonemeTable& table, double t);

}  // namespace fest::softobj
