#include "engines/lammps/LammpsEngine.hpp"
#include "engines/lammps/LammpsEngineFactory.hpp"

// LAMMPS's library interface declares lammps_open(..., MPI_Comm, ...) only with this defined.
#define LAMMPS_LIB_MPI 1
#include <library.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/io/CheckpointFile.hpp"
#include "engines/dem/LeesEdwardsImage.hpp"

namespace grainbridge::lammps {

namespace {

// Per-atom values gathered from every rank: id, type, x, v, omega, radius, mass, and v, omega
// at the last step's half step (contacts are evaluated there).
constexpr int kAtomColumns = 19;
// fix wall/gran's `contacts` array: in contact, force on the particle (3), contact point (3),
// radius.
constexpr int kWallColumns = 8;
// compute pair/local: dist, normal force on i (3), tangential force on i (p1-p3), normal
// relative velocity (p5-p7).
constexpr int kPairColumns = 10;

// Where gathered rows end up: on every rank (each rank puts back its own atoms' forces after a
// restart re-partitions them), or on the instance's first rank only (a frame of a million
// particles is held once, where it is written and sampled; the others get none).
enum class Gather { Everywhere, OnFirstRank };

// The rows every rank holds, gathered in rank order.
std::vector<double> gatherRows(MPI_Comm comm, std::vector<double> local, Gather where) {
  if (comm == MPI_COMM_NULL) return local;
  int size = 1;
  int rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  if (size == 1) return local;
  const bool everywhere = where == Gather::Everywhere;
  const int n = static_cast<int>(local.size());
  std::vector<int> counts(static_cast<std::size_t>(size));
  if (everywhere) {
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  } else {
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  }
  std::vector<int> displs(static_cast<std::size_t>(size), 0);
  std::vector<double> all;
  if (everywhere || rank == 0) {
    std::partial_sum(counts.begin(), std::prev(counts.end()), std::next(displs.begin()));
    all.resize(static_cast<std::size_t>(displs.back() + counts.back()));
  }
  if (everywhere) {
    MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm);
  } else {
    MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm);
  }
  return all;
}

// A Lees-Edwards offset (or a tilt) as an x shift in [0, L_x).
double wrappedOffset(double shift, double lengthX) {
  const double o = std::fmod(shift, lengthX);
  return o < 0 ? o + lengthX : o;
}

Vec3 row3(const double* r) { return {r[0], r[1], r[2]}; }

}  // namespace

LammpsEngine::LammpsEngine(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii, bool frozenAtoms,
                           std::int64_t lastStep, MPI_Comm comm, const std::filesystem::path& outputDir,
                           core::io::ArtifactStamp stamp)
    : setup_(setup), input_(lammpsInput(setup, radii, frozenAtoms)), frozenAtoms_(frozenAtoms), lastStep_(lastStep) {
  open(comm);
  if (leader()) writer_.emplace(outputDir, std::move(stamp));
}

LammpsEngine::LammpsEngine(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii,
                           const dem::Particles& particles, std::int64_t lastStep, MPI_Comm comm,
                           const std::filesystem::path& outputDir, core::io::ArtifactStamp stamp)
    : LammpsEngine(setup, radii,
                   std::any_of(particles.invMass.begin(),
                               particles.invMass.begin() + static_cast<std::ptrdiff_t>(particles.nOwned),
                               [](double w) { return w == 0.0; }),
                   lastStep, comm, outputDir, std::move(stamp)) {
  for (const auto& line : input_.system) command(line);
  const auto n = particles.nOwned;
  std::vector<int> ids(n), types(n);
  std::vector<double> x(3 * n), v(3 * n);
  std::unordered_map<std::int64_t, std::size_t> indexOf;
  for (std::size_t i = 0; i < n; ++i) {
    // LAMMPS counts atoms from 1; grainbridge's ids (inserted: from 0; a data file's: its own) map
    // to id + 1 and back.
    ids[i] = static_cast<int>(particles.id[i] + 1);
    types[i] = lammpsType(particles.species[i], particles.isFrozen(i), setup_.species);
    // Inside the (sheared: tilted by xy at the particle's height) periodic cell, or LAMMPS would
    // not create it.
    const double tilt = setup_.shearRate != 0.0 ? leesEdwardsInitialTilt(setup_) : 0.0;
    const double shift = tilt * (particles.x[i][1] - setup_.lo[1]) / (setup_.hi[1] - setup_.lo[1]);
    for (int a = 0; a < 3; ++a) {
      double xa = particles.x[i][a];
      if (setup_.periodic[static_cast<std::size_t>(a)]) {
        const double length = setup_.hi[a] - setup_.lo[a];
        const double lo = setup_.lo[a] + (a == 0 ? shift : 0.0);
        xa -= std::floor((xa - lo) / length) * length;
      }
      x[3 * i + a] = xa;
      v[3 * i + a] = particles.v[i][a];
    }
    indexOf[particles.id[i]] = i;
  }
  const int created =
      lammps_create_atoms(lmp_, static_cast<int>(n), ids.data(), types.data(), x.data(), v.data(), nullptr, 0);
  atoms_ = static_cast<std::int64_t>(lammps_get_natoms(lmp_));
  if (atoms_ != static_cast<std::int64_t>(n)) {
    throw Error("engine lammps: " + std::to_string(n - static_cast<std::size_t>(atoms_)) + " of " + std::to_string(n) +
                " particles lie outside the box and were not created (" + std::to_string(created) + " on this rank)");
  }
  // Radius, mass and spin per atom, on the rank that owns it.
  const int nlocal = *static_cast<int*>(lammps_extract_global(lmp_, "nlocal"));
  const int* tag = static_cast<int*>(lammps_extract_atom(lmp_, "id"));
  auto* radius = static_cast<double*>(lammps_extract_atom(lmp_, "radius"));
  auto* rmass = static_cast<double*>(lammps_extract_atom(lmp_, "rmass"));
  auto** omega = static_cast<double**>(lammps_extract_atom(lmp_, "omega"));
  for (int k = 0; k < nlocal; ++k) {
    const std::size_t i = indexOf.at(tag[k] - 1);
    radius[k] = particles.radius[i];
    rmass[k] = particles.mass[i];
    for (int a = 0; a < 3; ++a) omega[k][a] = particles.omega[i][a];
  }
  for (const auto& line : input_.interactions) command(line);
  makeWalls(0);
}

std::unique_ptr<LammpsEngine> LammpsEngine::restore(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii,
                                                    std::int64_t lastStep, const std::filesystem::path& stateFile,
                                                    const std::string& fingerprint, MPI_Comm comm,
                                                    const std::filesystem::path& outputDir,
                                                    core::io::ArtifactStamp stamp) {
  // The shared checkpoint header refuses another layout or another configuration's state.
  const auto file = core::io::openCheckpointFile(stateFile, {kCheckpointFormatVersion, fingerprint});
  const std::vector<std::uint8_t> restart = file.readBytes("/lammps_restart");
  std::vector<double> forces = file.readDoubles("/forces", {std::nullopt});
  const std::int64_t step = file.readIntAttribute("/", "step");
  const double time = file.readDoubleAttribute("/", "time");
  const bool frozenAtoms = file.readIntAttribute("/", "frozen_atoms") != 0;

  std::unique_ptr<LammpsEngine> engine(
      new LammpsEngine(setup, radii, frozenAtoms, lastStep, comm, outputDir, std::move(stamp)));
  // LAMMPS reads a restart from a file of its own, beside the state, written once (its first rank
  // reads it and sends the atoms to the others).
  const auto restartFile = std::filesystem::path(stateFile.string() + ".lammps-restart");
  if (engine->leader()) {
    std::ofstream(restartFile, std::ios::binary)
        .write(reinterpret_cast<const char*>(restart.data()), static_cast<std::streamsize>(restart.size()));
  }
  if (comm != MPI_COMM_NULL) MPI_Barrier(comm);
  engine->command("atom_modify map array");
  engine->command("read_restart " + restartFile.string());
  // The pair style, its coefficients and the contact histories are in the restart file; the
  // rest is issued again.
  for (const auto& line : engine->input_.interactions) {
    if (line.rfind("pair_", 0) == 0) continue;
    engine->command(line);
  }
  engine->makeWalls(step);
  if (comm != MPI_COMM_NULL) MPI_Barrier(comm);
  if (engine->leader()) std::filesystem::remove(restartFile);
  engine->restoredForces_ = std::move(forces);
  engine->forcesPending_ = true;
  engine->step_ = step;
  engine->time_ = time;
  engine->atoms_ = static_cast<std::int64_t>(lammps_get_natoms(engine->lmp_));
  return engine;
}

void LammpsEngine::makeWalls(std::int64_t step) {
  // A vibrating wall's phase counts from the step its fix is made at (LAMMPS's time_origin): the
  // step is set to the vibration's origin for that fix and back to `step` after it.
  bool moved = false;
  for (const auto& wall : input_.walls) {
    if (wall.vibrating) {
      command("reset_timestep " + std::to_string(wall.timeOrigin));
      moved = true;
    }
    command(wall.command);
  }
  if (moved) command("reset_timestep " + std::to_string(step));
}

LammpsEngine::~LammpsEngine() {
  if (lmp_ != nullptr) lammps_close(lmp_);
}

void LammpsEngine::open(MPI_Comm comm) {
  std::vector<std::string> args{"grainbridge", "-screen", "none", "-log", "none", "-nocite"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  comm_ = comm;
  lmp_ = comm == MPI_COMM_NULL ? lammps_open_no_mpi(static_cast<int>(argv.size()), argv.data(), nullptr)
                               : lammps_open(static_cast<int>(argv.size()), argv.data(), comm, nullptr);
  if (lmp_ == nullptr) throw Error("engine lammps: LAMMPS could not be opened");
}

void LammpsEngine::command(const std::string& line) const {
  spdlog::debug("lammps: {}", line);
  lammps_command(lmp_, line.c_str());
}

bool LammpsEngine::leader() const {
  if (comm_ == MPI_COMM_NULL) return true;
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  return rank == 0;
}

void LammpsEngine::flush() const {
  if (!setUp_) {
    // The setup run: neighbour lists and the forces of the initial state (no history update),
    // which the first step's half kick uses, as in a plain `run`.
    setupStep_ = step_ - pending_;
    command("run 0 start " + std::to_string(setupStep_) + " stop " + std::to_string(lastStep()) + " post no");
    setUp_ = true;
    if (forcesPending_) putBackForces();
  }
  if (pending_ == 0) return;
  // Under shear, LAMMPS (29 Sep 2021) ran the quickstart's sheared gas 1-2 % hotter than
  // grainbridge, more so the larger the neighbour skin, in its own binary too; with the lists
  // rebuilt on every step it gave grainbridge's temperature, and so it does with them rebuilt on
  // the few steps about each box flip (fix deform's tilt passing L_x / 2), which is what this
  // does (docs/dem.md, "engine lammps": 20 seeds, every closure quantity within 0.8 sigma). Where
  // in LAMMPS the heat comes from is not pinned down: the flip wraps particles without remap v's
  // velocity jump (Domain::remap), but a single grain crossing at a flip came through right.
  while (pending_ > 0) {
    std::int64_t chunk = pending_;
    bool window = false;
    if (setup_.shearRate != 0.0) {
      const std::int64_t k = stepsToFlip();
      if (k > 2) {
        chunk = std::min(pending_, k - 2);
      } else {
        window = true;
        chunk = std::min(pending_, k + 1);
      }
    }
    if (window) command("neigh_modify delay 0 every 1 check no");
    runSteps(chunk);
    if (window) command("neigh_modify delay 0 every 1 check yes");
    pending_ -= chunk;
  }
  halfStep_ = true;
  // A particle that leaves a fixed boundary stops the run, as on grainbridge's engine (LAMMPS
  // drops it: thermo_modify lost ignore keeps LAMMPS from ending the process).
  const auto atoms = static_cast<std::int64_t>(lammps_get_natoms(lmp_));
  if (atoms != atoms_) {
    throw Error("engine lammps: " + std::to_string(atoms_ - atoms) + " particle(s) left the domain through a " +
                "non-periodic boundary by step " + std::to_string(step_));
  }
}

void LammpsEngine::runSteps(std::int64_t steps) const {
  // `start` and `stop` as at the setup: fix deform interpolates its tilt between the two, as
  // its setup computed them, whatever the `pre no` run's own first and last steps.
  command("run " + std::to_string(steps) + " start " + std::to_string(setupStep_) + " stop " +
          std::to_string(lastStep()) + " pre no post no");
}

std::int64_t LammpsEngine::stepsToFlip() const {
  // The tilt grows by rate L_y dt per step; fix deform flips it once it would pass L_x / 2.
  const double tilt = *static_cast<double*>(lammps_extract_global(lmp_, "xy"));
  const double perStep = setup_.shearRate * (setup_.hi[1] - setup_.lo[1]) * setup_.dt;
  const double half = 0.5 * (setup_.hi[0] - setup_.lo[0]);
  const double room = perStep > 0.0 ? half - tilt : tilt + half;
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(room / std::abs(perStep))) + 1);
}

void LammpsEngine::putBackForces() const {
  std::unordered_map<std::int64_t, std::size_t> row;
  for (std::size_t k = 0; k < restoredForces_.size(); k += 7) row[static_cast<std::int64_t>(restoredForces_[k])] = k;
  const int nlocal = *static_cast<int*>(lammps_extract_global(lmp_, "nlocal"));
  const int* tag = static_cast<int*>(lammps_extract_atom(lmp_, "id"));
  auto** force = static_cast<double**>(lammps_extract_atom(lmp_, "f"));
  auto** torque = static_cast<double**>(lammps_extract_atom(lmp_, "torque"));
  for (int k = 0; k < nlocal; ++k) {
    const double* r = &restoredForces_.at(row.at(tag[k]));
    for (int a = 0; a < 3; ++a) {
      force[k][a] = r[1 + a];
      torque[k][a] = r[4 + a];
    }
  }
  forcesPending_ = false;
  halfStep_ = true;  // the forces held are the last step's again
}

void LammpsEngine::advance(bool observed) {
  frame_.reset();
  ++pending_;
  ++step_;
  time_ += setup_.dt;
  if (observed) flush();
}

void LammpsEngine::saveState(const std::filesystem::path& file, const std::string& fingerprint) const {
  flush();
  const auto restartFile = std::filesystem::path(file.string() + ".lammps-restart");
  command("write_restart " + restartFile.string());
  // The forces and torques of the last step (id, f, torque per atom): a restart does not hold
  // them, and LAMMPS's setup after read_restart would evaluate them at full-step velocities.
  const int nlocal = *static_cast<int*>(lammps_extract_global(lmp_, "nlocal"));
  const int* tag = static_cast<int*>(lammps_extract_atom(lmp_, "id"));
  auto** force = static_cast<double**>(lammps_extract_atom(lmp_, "f"));
  auto** torque = static_cast<double**>(lammps_extract_atom(lmp_, "torque"));
  std::vector<double> local;
  for (int k = 0; k < nlocal; ++k) {
    local.insert(local.end(), {static_cast<double>(tag[k]), force[k][0], force[k][1], force[k][2], torque[k][0],
                               torque[k][1], torque[k][2]});
  }
  const auto forces = gatherRows(comm_, std::move(local), Gather::Everywhere);
  // write_restart re-partitions the atoms (exchange, borders) and so leaves the neighbour lists
  // stale: the next run needs LAMMPS's setup, after which these forces are put back, as on a
  // resume.
  restoredForces_ = forces;
  forcesPending_ = true;
  setUp_ = false;
  if (!leader()) return;
  std::ifstream in(restartFile, std::ios::binary);
  const std::vector<std::uint8_t> restart((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && !in) throw Error(restartFile.string() + ": cannot read LAMMPS's restart file");
  // The shared checkpoint file (header, temporary, rename): LAMMPS's restart carried as bytes.
  core::io::writeCheckpointFile(file, {kCheckpointFormatVersion, fingerprint}, [&](core::io::H5OutputFile& f) {
    f.writeAttribute("/", "step", step_);
    f.writeAttribute("/", "time", time_);
    f.writeAttribute("/", "frozen_atoms", static_cast<std::int32_t>(frozenAtoms_ ? 1 : 0));
    f.writeBytes("/lammps_restart", restart);
    f.writeDataset("/forces", forces);
  });
  std::filesystem::remove(restartFile);
}

const core::data::ParticleFrame& LammpsEngine::frame() {
  flush();
  if (frame_) return *frame_;
  core::data::ParticleFrame f;
  f.time = time_;
  f.step = step_;
  f.domain.lo = setup_.lo;
  f.domain.hi = setup_.hi;
  f.domain.periodic = setup_.periodic;
  const Vec3 length = setup_.hi - setup_.lo;
  // grainbridge's Lees-Edwards offset of the image above, at this time (dem::Simulation's).
  const double offset = setup_.shearRate != 0.0 ? wrappedOffset(setup_.shearRate * length[1] * time_, length[0]) : 0.0;
  f.domain.leesEdwardsOffset = offset;
  f.domain.leesEdwardsShearRate = setup_.shearRate;
  // The offset of the ghosts the contacts are evaluated with: after a step, the one above (the
  // box's tilt one step back); in the state of a setup (the initial frame), the box's tilt now,
  // which is one step ahead of grainbridge's (the box starts at rate L_y dt, LammpsInput.cpp), so
  // a contact across the y boundary of the initial frame is that of the image at t = dt.
  const double ghostOffset = setup_.shearRate == 0.0 || halfStep_
                                 ? offset
                                 : wrappedOffset(*static_cast<double*>(lammps_extract_global(lmp_, "xy")), length[0]);
  for (const auto& w : setup_.walls) {
    f.domain.walls.push_back({w.kind == dem::Wall::Kind::Plane ? "plane" : "cylinder", w.positionAt(time_), w.direction,
                              w.kind == dem::Wall::Kind::Plane ? 0.0 : w.radius, w.velocityAt(time_)});
  }
  f.materials = materials_;

  // Particles, with the wall contact arrays alongside.
  const int nlocal = *static_cast<int*>(lammps_extract_global(lmp_, "nlocal"));
  const int* tag = static_cast<int*>(lammps_extract_atom(lmp_, "id"));
  const int* type = static_cast<int*>(lammps_extract_atom(lmp_, "type"));
  auto** x = static_cast<double**>(lammps_extract_atom(lmp_, "x"));
  auto** v = static_cast<double**>(lammps_extract_atom(lmp_, "v"));
  auto** omega = static_cast<double**>(lammps_extract_atom(lmp_, "omega"));
  const auto* radius = static_cast<double*>(lammps_extract_atom(lmp_, "radius"));
  const auto* rmass = static_cast<double*>(lammps_extract_atom(lmp_, "rmass"));
  const std::size_t walls = setup_.walls.size();
  const std::size_t width = kAtomColumns + kWallColumns * walls;
  std::vector<double> local;
  local.reserve(static_cast<std::size_t>(nlocal) * width);
  std::vector<double**> wallArrays;
  for (std::size_t w = 0; w < walls; ++w) {
    wallArrays.push_back(
        static_cast<double**>(lammps_extract_fix(lmp_, wallFixId(w).c_str(), LMP_STYLE_ATOM, LMP_TYPE_ARRAY, 0, 0)));
  }
  // The last step's half-step velocities: fix nve/sphere's final kick undone, v - dt/2 f/m (none
  // at the setup, whose forces are the state's own; none for a frozen atom).
  std::vector<double> half(6 * static_cast<std::size_t>(nlocal));
  {
    auto** force = static_cast<double**>(lammps_extract_atom(lmp_, "f"));
    auto** torque = static_cast<double**>(lammps_extract_atom(lmp_, "torque"));
    const double dtf = 0.5 * setup_.dt;
    for (int k = 0; k < nlocal; ++k) {
      const bool kicked = halfStep_ && type[k] <= setup_.species;
      const double dtfm = kicked ? dtf / rmass[k] : 0.0;
      const double dtirotate = kicked ? dtf / (0.4 * radius[k] * radius[k] * rmass[k]) : 0.0;
      for (int a = 0; a < 3; ++a) {
        half[6 * static_cast<std::size_t>(k) + static_cast<std::size_t>(a)] = v[k][a] - dtfm * force[k][a];
        half[6 * static_cast<std::size_t>(k) + 3 + static_cast<std::size_t>(a)] =
            omega[k][a] - dtirotate * torque[k][a];
      }
    }
  }
  for (int k = 0; k < nlocal; ++k) {
    local.insert(local.end(), {static_cast<double>(tag[k]), static_cast<double>(type[k]), x[k][0], x[k][1], x[k][2],
                               v[k][0], v[k][1], v[k][2], omega[k][0], omega[k][1], omega[k][2], radius[k], rmass[k]});
    local.insert(local.end(), half.begin() + 6 * k, half.begin() + 6 * k + 6);
    for (std::size_t w = 0; w < walls; ++w) {
      for (int c = 0; c < kWallColumns; ++c) local.push_back(wallArrays[w] ? wallArrays[w][k][c] : 0.0);
    }
  }
  const auto rows = gatherRows(comm_, std::move(local), Gather::OnFirstRank);
  const std::size_t n = rows.size() / width;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return rows[a * width] < rows[b * width]; });
  frozen_.assign(n, 0);
  std::unordered_map<std::int64_t, std::size_t> indexOf;
  std::vector<Vec3> halfV(n), halfOmega(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double* r = &rows[order[k] * width];
    const auto id = static_cast<std::int64_t>(r[0]) - 1;
    const int t = static_cast<int>(r[1]);
    indexOf[id] = k;
    f.id.push_back(id);
    f.species.push_back((t - 1) % setup_.species);
    frozen_[k] = t > setup_.species ? 1 : 0;
    Vec3 position = row3(r + 2);
    Vec3 velocity = row3(r + 5);
    // LAMMPS keeps a sheared box's particles in its tilted cell, and one that crossed y since its
    // last reneighbouring outside it; a frame holds the primary image, as grainbridge's engine's.
    if (setup_.shearRate != 0.0)
      dem::toPrimaryImage(position, velocity, setup_.lo, setup_.hi, offset, setup_.shearRate);
    f.position.push_back(position);
    f.velocity.push_back(velocity);
    f.angularVelocity.push_back(row3(r + 8));
    f.radius.push_back(r[11]);
    f.mass.push_back(r[12]);
    halfV[k] = row3(r + 13);
    halfOmega[k] = row3(r + 16);
    for (std::size_t w = 0; w < walls; ++w) {
      const double* c = r + kAtomColumns + kWallColumns * w;
      if (c[0] == 0.0) continue;
      const Vec3 force = row3(c + 1);
      // LAMMPS gives the point on the wall; grainbridge records the particle's surface point
      // along the normal, x - a n, which Eq. 2.3's wall term reads.
      const Vec3 normal = (f.position.back() - row3(c + 4)).normalized();
      f.wallContacts.particle.push_back(id);
      f.wallContacts.wall.push_back(static_cast<std::int32_t>(w));
      f.wallContacts.point.push_back(f.position.back() - f.radius.back() * normal);
      f.wallContacts.forceNormal.push_back(force.dot(normal) * normal);
      f.wallContacts.forceTangential.push_back(force - force.dot(normal) * normal);
    }
  }

  // Contacts as grainbridge's engine records them: the forces of the last step's evaluation, at
  // its half-step velocities. LAMMPS's computes evaluate the pairs at the atoms' velocities, so
  // the owned atoms are taken back to v(n+1/2) = v - dt/2 f/m (fix nve/sphere's own final kick,
  // undone; ghosts still hold the half-step values of the step's communication) while the
  // computes run, then restored bit for bit.
  std::vector<double> kept;
  if (halfStep_) {
    kept.reserve(6 * static_cast<std::size_t>(nlocal));
    for (int k = 0; k < nlocal; ++k) {
      for (int a = 0; a < 3; ++a) {
        kept.insert(kept.end(), {v[k][a], omega[k][a]});
        v[k][a] = half[6 * static_cast<std::size_t>(k) + static_cast<std::size_t>(a)];
        omega[k][a] = half[6 * static_cast<std::size_t>(k) + 3 + static_cast<std::size_t>(a)];
      }
    }
  }
  // The pairs' ids and their forces, row for row (both computes walk the same pairs with
  // `cutoff radius`; the distance column checks it).
  auto** pairIds =
      static_cast<double**>(lammps_extract_compute(lmp_, kPairAtomsCompute, LMP_STYLE_LOCAL, LMP_TYPE_ARRAY));
  const int idRows =
      *static_cast<int*>(lammps_extract_compute(lmp_, kPairAtomsCompute, LMP_STYLE_LOCAL, LMP_SIZE_ROWS));
  auto** pairForces =
      static_cast<double**>(lammps_extract_compute(lmp_, kPairForcesCompute, LMP_STYLE_LOCAL, LMP_TYPE_ARRAY));
  const int forceRows =
      *static_cast<int*>(lammps_extract_compute(lmp_, kPairForcesCompute, LMP_STYLE_LOCAL, LMP_SIZE_ROWS));
  if (idRows != forceRows) {
    throw Error("engine lammps: compute property/local lists " + std::to_string(idRows) +
                " pairs, compute pair/local " + std::to_string(forceRows));
  }
  std::vector<double> pairLocal;
  pairLocal.reserve(static_cast<std::size_t>(idRows) * (2 + kPairColumns));
  for (int k = 0; k < idRows; ++k) {
    pairLocal.push_back(pairIds[k][0]);
    pairLocal.push_back(pairIds[k][1]);
    for (int c = 0; c < kPairColumns; ++c) pairLocal.push_back(pairForces[k][c]);
  }
  if (halfStep_) {
    for (int k = 0; k < nlocal; ++k) {
      for (int a = 0; a < 3; ++a) {
        v[k][a] = kept[6 * static_cast<std::size_t>(k) + 2 * static_cast<std::size_t>(a)];
        omega[k][a] = kept[6 * static_cast<std::size_t>(k) + 2 * static_cast<std::size_t>(a) + 1];
      }
    }
  }
  const auto pairs = gatherRows(comm_, std::move(pairLocal), Gather::OnFirstRank);
  const bool hertzian = setup_.contact.normal == dem::contact::HertzSpring::name;
  const auto& m = setup_.material(0, 0);
  auto& cl = f.contacts;
  for (std::size_t k = 0; k < pairs.size(); k += 2 + kPairColumns) {
    const double* r = &pairs[k];
    const std::size_t i = indexOf.at(static_cast<std::int64_t>(r[0]) - 1);
    const std::size_t j = indexOf.at(static_cast<std::int64_t>(r[1]) - 1);
    // The minimum image; across the y boundary of a sheared box, the image is offset in x.
    Vec3 branch = f.position[i] - f.position[j];
    for (int a : {2, 1, 0}) {
      if (!setup_.periodic[static_cast<std::size_t>(a)]) continue;
      const double images = std::round(branch[a] / length[a]);
      branch[a] -= images * length[a];
      if (a == 1) branch[0] -= images * ghostOffset;
    }
    const double dist = r[2];
    // Rows of different pairs differ at O(1); the offsets of a long sheared run (rate L_y t, many
    // box lengths, reduced mod L_x) differ by the last bits of t between the two codes, 1e-12 m
    // after 1e5 steps of the quickstart's boxes.
    if (std::abs(branch.norm() - dist) > 1e-6 * dist) {
      std::array<char, 200> what{};
      std::snprintf(what.data(), what.size(), "distance %.17g against %.17g (branch %.17g %.17g %.17g)", dist,
                    branch.norm(), branch[0], branch[1], branch[2]);
      throw Error("engine lammps: compute pair/local and property/local disagree on a pair at step " +
                  std::to_string(step_) + " (" + what.data() + ") between ids " + std::to_string(f.id[i]) + " and " +
                  std::to_string(f.id[j]));
    }
    const Vec3 normal = branch / branch.norm();
    const double ai = f.radius[i];
    const double aj = f.radius[j];
    // Eq. 6.5's factor, and the elastic / dissipative split of Eqs. 6.5-6.6: the dissipative
    // parts are -f gamma m_eff v (normal: v_n, tangential: the contact point's slip velocity);
    // the elastic parts are what remains, which is -k u_t of LAMMPS's stored history also on a
    // sliding contact.
    const double scale = hertzian ? std::sqrt((ai + aj - dist) / (ai + aj)) : 1.0;
    const double meff = frozen_[i] != 0   ? f.mass[j]
                        : frozen_[j] != 0 ? f.mass[i]
                                          : f.mass[i] * f.mass[j] / (f.mass[i] + f.mass[j]);
    const Vec3 vij = halfV[i] - halfV[j];
    const Vec3 vn = row3(r + 9);
    const Vec3 slip = vij - vij.dot(normal) * normal - (ai * halfOmega[i] + aj * halfOmega[j]).cross(normal);
    const Vec3 fn = row3(r + 3);
    const Vec3 ft = row3(r + 6);
    const Vec3 fnDissipative = (-scale * m.gammaN * meff) * vn;
    const Vec3 ftDissipative = (-scale * m.gammaT * meff) * slip;
    cl.i.push_back(f.id[i]);
    cl.j.push_back(f.id[j]);
    cl.branch.push_back(branch);
    cl.contactPoint.push_back(f.position[i] - ai * normal);
    cl.forceNormal.push_back(fn);
    cl.forceTangential.push_back(ft);
    cl.forceNormalElastic.push_back(fn - fnDissipative);
    cl.forceNormalDissipative.push_back(fnDissipative);
    cl.forceTangentialElastic.push_back(ft - ftDissipative);
    cl.forceTangentialDissipative.push_back(ftDissipative);
  }
  frame_ = std::move(f);
  return *frame_;
}

dem::Energies LammpsEngine::energies() {
  const auto& f = frame();
  dem::Energies e;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (frozen_[i] != 0) continue;
    e.translational += 0.5 * f.mass[i] * f.velocity[i].squaredNorm();
    e.rotational += 0.5 * (0.4 * f.mass[i] * f.radius[i] * f.radius[i]) * f.angularVelocity[i].squaredNorm();
  }
  return e;
}

std::int64_t LammpsEngine::mobileCount() {
  frame();
  return std::count(frozen_.begin(), frozen_.end(), 0);
}

std::vector<Vec3> LammpsEngine::wallForces() {
  const auto& f = frame();
  std::vector<Vec3> out(setup_.walls.size(), Vec3::Zero());
  const auto& wc = f.wallContacts;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    out[static_cast<std::size_t>(wc.wall[k])] -= wc.forceNormal[k] + wc.forceTangential[k];
  }
  return out;
}

void LammpsEngine::writeFrames() {
  const auto& f = frame();
  if (writer_) writer_->write(f);
}

bool LammpsEngine::writeFramesIfUsable() {
  const auto& f = frame();
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!f.position[i].allFinite() || !f.velocity[i].allFinite()) return false;
  }
  writeFrames();
  return true;
}

std::string LammpsEngine::throughputNote() const {
  return "on LAMMPS " + std::to_string(lammps_version(lmp_)) + " (GRANULAR)";
}

std::unique_ptr<dem::ParticleEngine> startLammpsEngine(const dem::ParticleEngineStart& start,
                                                       dem::Particles particles) {
  return std::make_unique<LammpsEngine>(start.setup, LammpsSpeciesRadii{start.speciesRadii}, particles, start.lastStep,
                                        start.comm, start.outputDir, start.stamp);
}

std::unique_ptr<dem::ParticleEngine> restoreLammpsEngine(const dem::ParticleEngineStart& start,
                                                         const std::filesystem::path& state,
                                                         const std::string& fingerprint) {
  return LammpsEngine::restore(start.setup, LammpsSpeciesRadii{start.speciesRadii}, start.lastStep, state, fingerprint,
                               start.comm, start.outputDir, start.stamp);
}

}  // namespace grainbridge::lammps
