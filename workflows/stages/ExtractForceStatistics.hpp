#pragma once
// The extract stage's force statistics (force_statistics: true), pooled over the averaged
// frames: the force PDF of f = F_n/<F_n> with its Eq. 6.11 and 6.13 fits, the force (Eq. 6.12)
// and velocity correlations with their lengths, the velocity kurtosis (Section 8.2.1.1); and,
// with structure: true as well, the same PDF, fits and force correlation for the contacts each
// multi-pass MST pass has found (Figs. 6.14-6.16).
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/data/ParticleFrame.hpp"
#include "workflows/stages/StageContext.hpp"

namespace grainbridge::workflows::stages {

// Writes force_pdf.csv and correlations.csv, records force_statistics rows (source "contacts"),
// and adds the correlation lengths and the kurtosis to the closure point `point`. Velocity
// statistics use every frame. With no repulsive contact in any frame (a dilute gas) there is no
// force PDF: the point's extra_json says why (force_statistics_skipped) and the run goes on.
void addForceStatistics(StageContext& ctx, const std::vector<core::data::ParticleFrame>& frames, double diameter,
                        nlohmann::json& point);

// treeContacts[f][p]: indices into frames[f].contacts of the contacts MST passes 1..p+1 found
// (extract/structure/MstTreeContacts.hpp). Forces are normalised by the mean over all repulsive
// contacts of their frame, as Fig. 6.14 compares them with the force networks' PDF (so the
// one-pass PDF sits at larger f). Writes mst_force_pdf.csv and mst_correlations.csv (one block
// per pass) and records force_statistics rows with source "mst_pass<p>".
void addMstForceStatistics(StageContext& ctx, const std::vector<core::data::ParticleFrame>& frames,
                           const std::vector<std::vector<std::vector<std::size_t>>>& treeContacts, double diameter);

}  // namespace grainbridge::workflows::stages
