// The incident sea of a scene's record evaluated once (sea/incident_wave_record.hpp) for its
// floating box hull: patches at the hull's sides over the motion range of wave.kinematics_*_range,
// the record over simulation.duration within wave.kinematics_tolerance. Built once per distinct
// sea, hull and settings and shared (a process-wide cache of weak references: compare, sweep and
// recommend build several models of one scene, and an operability table runs many records on
// threads; a record lives while a model uses it).
#pragma once

#include <memory>
#include <string>

#include "multibody/crane_parameters.hpp"
#include "scene/scene.hpp"

namespace ffrf::scene {

// What the hull loads of a scene read the incident wave from, for reports.
struct WaveKinematicsChoice {
  std::string method = "exact";  // "precomputed" | "exact"
  std::string reason;            // why exact: chosen, regular wave, BEM excitation, finite depth, …
};

// The record for `hull` (its section, and its floating pose in support_pose) in `wave`, or nullptr
// with `choice` saying why not. Throws SceneError naming wave.kinematics when the record would not
// fit in memory (the size and the way out in the message).
std::shared_ptr<const sea::IncidentWaveRecord> recorded_sea(const Scene& scene, const multibody::HullModel& hull,
                                                                 const sea::WaveField& wave,
                                                                 WaveKinematicsChoice* choice = nullptr);

// The choice for a scene without building anything (the record's own reasons come from building it).
WaveKinematicsChoice wave_kinematics_choice(const Scene& scene);

}  // namespace ffrf::scene
