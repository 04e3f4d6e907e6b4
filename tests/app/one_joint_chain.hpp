#pragma once
// A small chain file shared by the chain-warning tests (soft chain, near resonance, chain
// against wing): two 20 mm bodies on a rigid root, 0.01 g + 0.1 g = 110 mg, 40 mm from the
// pivot. Body 2: mass m = 1e-4 kg at y = 10 mm from its joint, I_xx = 1e-9 kg m², bend
// spring k = 1e-3 N m/rad. Bending about x at the joint: I = I_xx + m y² = 1.1e-8 kg m²,
// f = sqrt(k / I) / 2π = 47.99 Hz; twist: I_yy = 1e-10 kg m² with 1e-3 N m/rad, 503 Hz.
// Format: docs/multibody.md (the chain file).

#include <fstream>
#include <string>

#include "common/scratch_dir.hpp"
#include "pipeline/io/case_file.hpp"

namespace flapsim::test {

inline constexpr const char* kOneJointChain =
    "root = \"rigid\"\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-5\ncenter_of_mass = [0, 0.01, 0]\n"
    "inertia = [[4e-10,0,0],[0,1e-11,0],[0,0,4e-10]]\n"
    "[[bodies]]\nlength = 0.02\nmass = 1e-4\ncenter_of_mass = [0, 0.01, 0]\n"
    "inertia = [[1e-9,0,0],[0,1e-10,0],[0,0,1e-9]]\n"
    "[bodies.joint]\nbend_stiffness = 1e-3\ntwist_stiffness = 1e-3\n";

/// The chain above as DIR/chain.toml and a two-body flexible case in vacuum that uses it,
/// flapped at frequency_hz with a 50° sweep, `rotation` (a case-file line) and `extra`
/// (further case-file lines), read back as a Case.
inline io::Case load_one_joint_case(const ScratchDir& dir, double frequency_hz, const std::string& rotation,
                                    const std::string& extra = "") {
  std::ofstream(dir / "chain.toml") << kOneJointChain;
  std::ofstream(dir / "case.toml") << "air = \"none\"\nchain = \"chain.toml\"\n[kinematics]\nfrequency_hz = "
                                   << frequency_hz << "\nsweep = { cos_deg = [50.0] }\n" << rotation
                                   << "\n[structure]\nkind = \"flexible\"\nbodies = 2\n" << extra;
  return io::load_case_file((dir / "case.toml").string());
}

/// The chain above followed by `chain_tail` (a [fem_comparison] table) as DIR/chain.toml, and
/// DIR/case.toml: a two-body flexible case in vacuum that uses it, 10 Hz, 8 steps, no frames.
inline void write_one_joint_run_case(const ScratchDir& dir, const std::string& chain_tail) {
  std::ofstream(dir / "chain.toml") << kOneJointChain << chain_tail;
  std::ofstream(dir / "case.toml")
      << "air = \"none\"\nchain = \"chain.toml\"\n[kinematics]\nfrequency_hz = 10\n"
         "sweep = { cos_deg = [50.0] }\nrotation = 90.0\n"
         "[structure]\nkind = \"flexible\"\nbodies = 2\n"
         "[numerics]\nsteps_per_cycle = 8\ncycles = 1\n[output]\nvtk_every = 0\n";
}

}  // namespace flapsim::test
