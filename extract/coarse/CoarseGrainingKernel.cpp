#include "extract/coarse/CoarseGrainingKernel.hpp"

#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::extract::coarse {

CoarseGrainingKernel CoarseGrainingKernel::fromName(std::string_view name, double width) {
  if (name == "bin") return bin();
  if (name == "overlap") return overlap();
  if (name == "gaussian") return gaussian(width);
  if (name == "lucy") return lucy(width);
  throw Error("coarse graining: unknown kernel '" + std::string(name) +
              "', expected one of bin, overlap, gaussian, lucy");
}

std::string CoarseGrainingKernel::name() const {
  switch (kind) {
    case KernelKind::Bin:
      return "bin";
    case KernelKind::Overlap:
      return "overlap";
    case KernelKind::Gaussian:
      return "gaussian";
    case KernelKind::Lucy:
      return "lucy";
  }
  return "unknown";
}

std::optional<core::grid::SmoothingKernel> CoarseGrainingKernel::smoothingKernel() const {
  if (!smooth()) return std::nullopt;
  if (!(width > 0.0)) {
    std::ostringstream msg;
    msg << "coarse graining: kernel width " << width << " must be positive (" << name() << " kernel)";
    throw Error(msg.str());
  }
  if (kind == KernelKind::Gaussian) return core::grid::SmoothingKernel(core::grid::GaussianKernel(width));
  return core::grid::SmoothingKernel(core::grid::LucyKernel(width));
}

}  // namespace grainbridge::extract::coarse
