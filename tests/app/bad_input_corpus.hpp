// The bad-input corpus: scenes that each carry one mistake, generated from the scene
// schema so that a new key gets its cases without anyone writing them, plus cross-key physics,
// command-line misuse and output paths. Shared here: writing a key into a shipped scene, the
// generated scene cases, and the checks every case makes on what the user sees.
#pragma once

#include <string>
#include <vector>

#include "cli_harness.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::test {

// A scene with one key written: the text, the 1-based line of the key and the value as written.
struct EditedScene {
  std::string text;
  int line = 0;
  std::string written;
};

// The shipped scene a key is tried in: the reference crane, or the dropped-load hub for [hub].
std::string base_scene_for(const scene::KeySpec& key);
// `dotted = value` written into `text`: the key's line replaced, or added under its section (the
// section appended when absent); the other keys of its one-of group removed.
EditedScene with_key(const std::string& text, const scene::KeySpec& key, const std::string& value);

// One generated scene case: a key given a bad value of some kind.
struct SceneCase {
  std::string name;      // "boom_length_above_range"
  std::string key;       // "boom.length"
  EditedScene scene;
  std::string expected;  // in the message: "valid range [0.1, 1000] m", the choices, ...
};
// For every number key: beyond its range above and below, NaN, text, a unit of another dimension
// (and a bare number for an angle); for every whole-number key: 2^32 + 1, −1, 2.5 and text; for
// every choice key: an unknown keyword and a number; for every text key: a number.
std::vector<SceneCase> generated_scene_cases();

// Library or runtime text that must never reach a user.
inline const std::vector<std::string> kBareLibraryText{
    "bad_alloc", "logic_error", "std::", "vector::", "basic_string", "_M_", "stoi", "stod", "filesystem error",
    "terminate called", "what():", "Could not convert", "CLI11", "Segmentation", "Aborted", "nan\n", "-nan"};

// The CLI run of one corpus case: `ffrf ARGS` under a 30 s timeout, stdin from /dev/null.
struct TimedRun {
  int exit_code;  // 124: the timeout fired
  std::string out, err;
  double seconds;
};
TimedRun run_ffrf_timed(const std::string& args, const fs::path& scratch, const std::string& prefix = {});

}  // namespace ffrf::test
