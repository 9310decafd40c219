#include "db/Migrations.hpp"

namespace grainbridge::db {

const std::vector<std::string>& migrations() {
  static const std::vector<std::string> scripts = {
      // 1: provenance (invocations, runs and their inputs, artifacts), the stage cache and the
      // leases that replace lock files. instance_dir and artifact paths are relative to the
      // results root, so a moved project keeps working. Plain CREATE TABLE (no IF NOT EXISTS):
      // running a migration twice is a bug that should fail loudly.
      R"sql(
CREATE TABLE invocations(
  id INTEGER PRIMARY KEY,
  workflow TEXT NOT NULL,
  config_path TEXT,
  config_json TEXT NOT NULL,
  code_version TEXT NOT NULL,
  code_dirty INTEGER NOT NULL,
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  ranks INTEGER NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT,
  status TEXT NOT NULL CHECK(status IN ('running','done','failed','killed')));

CREATE TABLE runs(
  id INTEGER PRIMARY KEY,
  invocation_id INTEGER NOT NULL REFERENCES invocations(id),
  workflow TEXT NOT NULL,
  stage TEXT NOT NULL,
  stage_type TEXT NOT NULL,
  impl_version INTEGER NOT NULL,
  key TEXT NOT NULL,
  params_json TEXT NOT NULL,
  instance_dir TEXT NOT NULL,
  code_version TEXT NOT NULL,
  code_dirty INTEGER NOT NULL,
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  rank INTEGER NOT NULL,
  ranks INTEGER NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT,
  status TEXT NOT NULL CHECK(status IN ('running','done','failed','killed')),
  error TEXT,
  summary_json TEXT);
CREATE INDEX runs_key ON runs(key);
CREATE INDEX runs_workflow_stage ON runs(workflow, stage);
CREATE INDEX runs_invocation ON runs(invocation_id);

CREATE TABLE run_inputs(
  run_id INTEGER NOT NULL REFERENCES runs(id),
  upstream_key TEXT NOT NULL,
  PRIMARY KEY(run_id, upstream_key));

CREATE TABLE artifacts(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  key TEXT NOT NULL,
  path TEXT NOT NULL,
  kind TEXT NOT NULL,
  sha256 TEXT NOT NULL,
  bytes INTEGER NOT NULL,
  UNIQUE(run_id, path));
CREATE INDEX artifacts_key ON artifacts(key);

CREATE TABLE stage_cache(
  key TEXT PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  workflow TEXT NOT NULL,
  stage TEXT NOT NULL,
  instance_dir TEXT NOT NULL,
  completed_at TEXT NOT NULL);
CREATE INDEX stage_cache_workflow ON stage_cache(workflow, stage);

CREATE TABLE leases(
  key TEXT PRIMARY KEY,
  run_id INTEGER REFERENCES runs(id),
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  pid_start TEXT NOT NULL,
  claimed_at TEXT NOT NULL,
  heartbeat_at TEXT NOT NULL);
CREATE INDEX leases_run ON leases(run_id);
)sql",
      // 2: the closure database (DESIGN.md "Closures"). A closure point is one DEM state and what
      // was measured there, SI and dimensionless, each with its uncertainty, tied to the run that
      // produced it (and through runs/run_inputs to everything upstream). Force and structure
      // statistics are per frame or per set of frames. A closure table is a named grid of one
      // dimensionless quantity that loads into core::ClosureTable.
      R"sql(
CREATE TABLE closure_points(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  family TEXT NOT NULL,
  species TEXT NOT NULL DEFAULT 'all',
  solid_fraction REAL NOT NULL CHECK(solid_fraction >= 0 AND solid_fraction < 1),
  restitution REAL,
  friction REAL,
  shear_rate REAL,
  diameter REAL NOT NULL CHECK(diameter > 0),
  density REAL NOT NULL CHECK(density > 0),
  frames INTEGER NOT NULL,
  granular_temperature REAL, granular_temperature_err REAL,
  pressure REAL, pressure_err REAL,
  shear_stress REAL, shear_stress_err REAL,
  viscosity REAL, viscosity_err REAL,
  dissipation_rate REAL, dissipation_rate_err REAL,
  coordination REAL, coordination_err REAL,
  force_correlation_length REAL, force_correlation_length_err REAL,
  velocity_correlation_length REAL, velocity_correlation_length_err REAL,
  p_theta REAL, p_theta_err REAL,
  eta_theta REAL, eta_theta_err REAL,
  j_theta REAL, j_theta_err REAL,
  p_shear REAL, p_shear_err REAL,
  tau_shear REAL, tau_shear_err REAL,
  t_shear REAL, t_shear_err REAL,
  extra_json TEXT);
CREATE INDEX closure_points_state ON closure_points(family, solid_fraction, restitution, friction);
CREATE INDEX closure_points_run ON closure_points(run_id);

CREATE TABLE force_statistics(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  family TEXT NOT NULL,
  source TEXT NOT NULL,
  frame_step INTEGER,
  time REAL,
  forces INTEGER NOT NULL,
  mean_force REAL,
  model TEXT NOT NULL,
  a REAL, a_err REAL, b REAL, b_err REAL, beta REAL, beta_err REAL,
  alpha REAL, alpha_err REAL, gamma REAL, gamma_err REAL,
  chi2_dof REAL, density_integral REAL,
  correlation_length REAL, correlation_length_err REAL,
  extra_json TEXT);
CREATE INDEX force_statistics_run ON force_statistics(run_id);

CREATE TABLE structure_statistics(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  family TEXT NOT NULL,
  kind TEXT NOT NULL CHECK(kind IN ('force_networks','mst')),
  pass INTEGER NOT NULL DEFAULT 0,
  frame_step INTEGER,
  time REAL,
  networks INTEGER,
  largest_particles INTEGER, largest_edges INTEGER,
  largest_coordination REAL,
  strong_particles INTEGER,
  largest_extent REAL,
  other_trees INTEGER, other_edges INTEGER,
  extra_json TEXT);
CREATE INDEX structure_statistics_run ON structure_statistics(run_id);

CREATE TABLE closure_tables(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  name TEXT NOT NULL,
  quantity TEXT NOT NULL,
  second_variable TEXT NOT NULL DEFAULT '',
  solid_fractions_json TEXT NOT NULL,
  seconds_json TEXT NOT NULL,
  values_json TEXT NOT NULL,
  uncertainties_json TEXT NOT NULL,
  filters_json TEXT NOT NULL DEFAULT '{}',
  UNIQUE(run_id, name, quantity));
CREATE INDEX closure_tables_name ON closure_tables(name, quantity);
)sql",
      // 3: a sheared closure point's dense-flow variables (issue 30): the inertial number and
      // the stress ratio tau / p, each with its error (extract's ClosurePointObserver).
      R"sql(
ALTER TABLE closure_points ADD COLUMN inertial_number REAL;
ALTER TABLE closure_points ADD COLUMN inertial_number_err REAL;
ALTER TABLE closure_points ADD COLUMN stress_ratio REAL;
ALTER TABLE closure_points ADD COLUMN stress_ratio_err REAL;
)sql",
      // 4: the dense-flow rheology a tabulate stage makes (issue 30): per restitution, the
      // points of mu(I) (stress ratio) or phi(I) (solid fraction) against the inertial number,
      // and the fit of mu_s + (mu_2 - mu_s) / (1 + I_0 / I) or phi_c - a I with its errors
      // (extract/statistics/InertialRheologyFit). The fit columns are NULL when the points were
      // too few to fit. diameter and density name the grains, so a continuum stage can refuse
      // a rheology made from other grains.
      R"sql(
CREATE TABLE rheology(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  name TEXT NOT NULL,
  family TEXT NOT NULL,
  relation TEXT NOT NULL CHECK(relation IN ('mu_of_I', 'phi_of_I')),
  form TEXT NOT NULL,
  restitution REAL,
  friction REAL,
  diameter REAL NOT NULL CHECK(diameter > 0),
  density REAL NOT NULL CHECK(density > 0),
  points INTEGER NOT NULL,
  inertial_numbers_json TEXT NOT NULL,
  inertial_number_errors_json TEXT NOT NULL,
  values_json TEXT NOT NULL,
  uncertainties_json TEXT NOT NULL,
  fit_inertial_number_max REAL,
  fitted_points INTEGER,
  mu_s REAL, mu_s_err REAL,
  mu_2 REAL, mu_2_err REAL,
  inertial_number_0 REAL, inertial_number_0_err REAL,
  phi_c REAL, phi_c_err REAL,
  slope REAL, slope_err REAL,
  covariance_json TEXT,
  chi2_per_dof REAL,
  dof INTEGER,
  weighted INTEGER);
CREATE INDEX rheology_name ON rheology(name, relation);
)sql",
      // 5: closure points of a mixture's species and species pairs (issue 60). A species' row
      // has its own partial solid fraction in solid_fraction; the mixture's total and the species'
      // share of the solids volume (x) are the state the row belongs to. NULL for one species.
      R"sql(
ALTER TABLE closure_points ADD COLUMN mixture_solid_fraction REAL;
ALTER TABLE closure_points ADD COLUMN volume_share REAL;
)sql",
      // 6: a closure point's theta forms' correlation coefficients and its error warning (issue
      // 63): p_theta, eta_theta and j_theta share the point's temperature (and under shear
      // eta_theta and j_theta its shear stress), so their errors are correlated; error_warning
      // says which quantities' blocking curves reached no plateau (their errors are lower
      // bounds). A table's correlations_json holds, per other quantity of its point, the
      // coefficient at each node ({"eta_theta": [...], ...}), for drawing a node's quantities
      // jointly (core/ClosureTableDraw).
      R"sql(
ALTER TABLE closure_points ADD COLUMN p_theta_eta_theta_corr REAL;
ALTER TABLE closure_points ADD COLUMN p_theta_j_theta_corr REAL;
ALTER TABLE closure_points ADD COLUMN eta_theta_j_theta_corr REAL;
ALTER TABLE closure_points ADD COLUMN error_warning TEXT;
ALTER TABLE closure_tables ADD COLUMN correlations_json TEXT NOT NULL DEFAULT '{}';
)sql",
      // 7: how ordered a closure point's box was (issue 61): the bond-orientational order q6 and
      // the share of crystalline grains (extract/structure/BondOrder), each time-averaged with
      // its error, and ordered = 1 where that share exceeds 0.2 (tabulate leaves such points out
      // unless keep_ordered). NULL for points made before it.
      R"sql(
ALTER TABLE closure_points ADD COLUMN bond_order_q6 REAL;
ALTER TABLE closure_points ADD COLUMN bond_order_q6_err REAL;
ALTER TABLE closure_points ADD COLUMN crystalline_share REAL;
ALTER TABLE closure_points ADD COLUMN crystalline_share_err REAL;
ALTER TABLE closure_points ADD COLUMN ordered INTEGER;
)sql",
      // 8: the power-law forms of the dense rheology near the critical point (issue 61):
      // mu_c + mu_amplitude I^mu_exponent and phi_c_power - phi_amplitude I^phi_exponent, in rows
      // of their own (relation mu_of_I or phi_of_I, form naming the law).
      R"sql(
ALTER TABLE rheology ADD COLUMN mu_c REAL;
ALTER TABLE rheology ADD COLUMN mu_c_err REAL;
ALTER TABLE rheology ADD COLUMN mu_amplitude REAL;
ALTER TABLE rheology ADD COLUMN mu_amplitude_err REAL;
ALTER TABLE rheology ADD COLUMN mu_exponent REAL;
ALTER TABLE rheology ADD COLUMN mu_exponent_err REAL;
ALTER TABLE rheology ADD COLUMN phi_c_power REAL;
ALTER TABLE rheology ADD COLUMN phi_c_power_err REAL;
ALTER TABLE rheology ADD COLUMN phi_amplitude REAL;
ALTER TABLE rheology ADD COLUMN phi_amplitude_err REAL;
ALTER TABLE rheology ADD COLUMN phi_exponent REAL;
ALTER TABLE rheology ADD COLUMN phi_exponent_err REAL;
)sql",
      // 9: a table's third axis (issue 60: a mixture species' table over total solid fraction,
      // volume share and restitution); '' and [] for tables of one or two axes.
      R"sql(
ALTER TABLE closure_tables ADD COLUMN third_variable TEXT NOT NULL DEFAULT '';
ALTER TABLE closure_tables ADD COLUMN thirds_json TEXT NOT NULL DEFAULT '[]';
)sql",
  };
  return scripts;
}

}  // namespace grainbridge::db
