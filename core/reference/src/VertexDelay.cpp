#include "VertexDelay.h"

#include <algorithm>
#include <cmath>

namespace tofsim::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;

// A uniform in (0, 1]: log of it is finite.
double openUniform(Pcg32& rng) { return 1.0 - rng.nextDouble(); }

// N(0, 1) by Box-Muller (one of the pair).
double standardNormal(Pcg32& rng) {
  const double r = std::sqrt(-2.0 * std::log(openUniform(rng)));
  return r * std::cos(2.0 * kPi * rng.nextDouble());
}
}  // namespace

DelaySampler::DelaySampler(const physics::ResponseKernel& kernel) : kernel_(kernel) {
  // The stage's own validation (ranges, a table's area), at a bin of 1 s:
  // the kernel is checked once, by the same rules, and never reaches the
  // tap limit at that width for the kernels a config can hold.
  (void)physics::responseTaps(kernel, 1.0);
  if (kernel.model != physics::ResponseModel::Table) return;
  const std::vector<double>& t = kernel.tableDelay_s;
  const std::vector<double>& w = kernel.tableWeight;
  cumulative_.assign(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i) {
    cumulative_[i] = cumulative_[i - 1] + 0.5 * (t[i] - t[i - 1]) * (w[i - 1] + w[i]);
  }
  const double area = cumulative_.back();
  for (double& c : cumulative_) c /= area;
}

double DelaySampler::sampleTable(double u) const {
  const std::vector<double>& t = kernel_.tableDelay_s;
  const std::vector<double>& w = kernel_.tableWeight;
  // The piece whose cumulative share holds u (a piece of zero area is never chosen).
  const auto upper = std::upper_bound(cumulative_.begin() + 1, cumulative_.end(), u);
  const std::size_t i =
      std::min<std::size_t>(static_cast<std::size_t>(upper - cumulative_.begin()), t.size() - 1) - 1;
  const double width = t[i + 1] - t[i];
  if (!(width > 0.0)) return t[i];
  // Within the piece the density is a + b x (x = t - t[i], in the table's
  // weights): solve a x + b x^2 / 2 = the piece's area still to cover, in
  // the form without cancellation, x = 2 need / (a + sqrt(a^2 + 2 b need)).
  const double share = cumulative_[i + 1] - cumulative_[i];
  const double need = (u - cumulative_[i]) / share * 0.5 * width * (w[i] + w[i + 1]);
  if (!(need > 0.0)) return t[i];
  const double a = w[i], b = (w[i + 1] - w[i]) / width;
  const double x = 2.0 * need / (a + std::sqrt(std::max(0.0, a * a + 2.0 * b * need)));
  return t[i] + std::clamp(x, 0.0, width);
}

double DelaySampler::sample(Pcg32& rng) const {
  switch (kernel_.model) {
    case physics::ResponseModel::Exponential:
      return -kernel_.lifetime_s * std::log(openUniform(rng));
    case physics::ResponseModel::Gaussian:
      // Truncated to t >= 0 and renormalised (ResponseKernel): rejection
      // keeps the shape; with mean >= 0 at least half the draws are kept.
      for (;;) {
        const double t = kernel_.mean_s + kernel_.sigma_s * standardNormal(rng);
        if (t >= 0.0) return t;
      }
    case physics::ResponseModel::Table:
      return sampleTable(rng.nextDouble());
  }
  return 0.0;
}

void PathWeight::scale(const glm::dvec3& w) {
  if (!matrix_) {
    diagonal_ *= w;
    return;
  }
  for (int c = 0; c < 3; ++c) (*matrix_)[c] *= w[c];  // matrix * diag(w)
}

void PathWeight::reemit(const glm::dmat3& m) {
  if (!matrix_) {
    matrix_ = glm::dmat3(1.0);
    for (int c = 0; c < 3; ++c) (*matrix_)[c][c] = diagonal_[c];
  }
  *matrix_ = *matrix_ * m;
}

glm::dvec3 PathWeight::apply(const glm::dvec3& radiance) const {
  return matrix_ ? *matrix_ * radiance : diagonal_ * radiance;
}

VertexDelays::VertexDelays(const std::vector<physics::ResponseKernel>& kernels) {
  samplers_.reserve(kernels.size());
  for (const physics::ResponseKernel& k : kernels) samplers_.emplace_back(k);
}

void VertexDelays::atVertex(int32_t response, Pcg32& rng, PathState& state) const {
  if (response <= 0) return;
  const DelaySampler& s = samplers_.at(static_cast<std::size_t>(response - 1));
  if (!(rng.nextDouble() < s.fraction())) return;  // prompt
  state.delay_s += s.sample(rng);
  if (s.reemits()) state.weight.reemit(s.reemission());
}

void VertexDelays::atLight(int32_t response, Pcg32& rng, PathState& state) const {
  if (response <= 0) return;
  const DelaySampler& s = samplers_.at(static_cast<std::size_t>(response - 1));
  if (!(rng.nextDouble() < s.fraction())) return;  // prompt
  state.delay_s += s.sample(rng);
  if (s.reemits()) state.atLight = s.reemission();
}

}  // namespace tofsim::reference
