// Hydrostatic + Froude–Krylov hull load with the incident wave read from a record of the sea: the
// wetted boundary and the piece integrals from the recorded F, G, H (see hull_pressure_recorded.hpp,
// docs/hydrodynamics.md, "The sea evaluated once").
#include "sea/hull_pressure_recorded.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <complex>

#include "sea/component_phasors.hpp"
#include "sea/crossing_isolation.hpp"
#include "sea/hull_edges.hpp"
#include "hydro/gauss_legendre.hpp"

namespace ffrf::sea {

namespace {

constexpr double root_tolerance = 1e-12;  // in the edge parameter s ∈ [0, 1]
constexpr int max_root_iterations = 60;
// A crest piece spanning less than this in x is integrated by Gauss–Legendre on ζ (its antiderivative
// would divide by the small span); 4 points are exact to degree 7 in x: (k Δx/2)⁸/8! ≈ 2e-9 at k = 0.6.
constexpr double crest_quadrature_span = 1.0;  // [m]
constexpr int crest_quadrature_points = 4;

// The edge's pressure moments from the record at one time; false where the record cannot answer.
class RecordedEdges {
 public:
  RecordedEdges(const IncidentWaveRecord& record, const WaveField& wave, const WavePolynomials& poly, const Eigen::Vector2d& g1)
      : record_(record), wave_(wave), poly_(poly), g1_(g1), bound_(record.elevation_bound(poly.time, poly.ramp)),
        slope_(record.slope_bound(poly.time, poly.ramp)) {}

  bool moments(const HullEdge& edge, EdgeMoments& acc) const {
    const double ya = edge.a.y(), yb = edge.a.y() + edge.d.y();
    if (std::max(ya, yb) < -bound_) return wetted(edge, 0.0, 1.0, acc);  // below every trough
    if (std::min(ya, yb) > bound_) return true;                          // above every crest
    const double xa = edge.a.x(), xb = edge.a.x() + edge.d.x();
    if (std::min(xa, xb) < record_.x_min() || std::max(xa, xb) > record_.x_max()) return false;
    // A side steeper than the surface: g(s) = y(s) − ζ(x(s)) has g' = d_y − d_x ζ' of the sign of d_y,
    // so it crosses once at most, inside the part of the edge with |y| ≤ the elevation bound.
    if (std::abs(edge.d.y()) > std::abs(edge.d.x()) * slope_) {
      const double s_low = std::clamp((-bound_ - ya) / edge.d.y(), 0.0, 1.0);  // y = −bound: wet
      const double s_high = std::clamp((bound_ - ya) / edge.d.y(), 0.0, 1.0);  // y = +bound: dry
      double crossing = 0.0;
      if (!surface_crossing(edge, s_low, s_high, crossing)) return false;
      return edge.d.y() > 0.0 ? wetted(edge, 0.0, crossing, acc) : wetted(edge, crossing, 1.0, acc);
    }
    return crossings_along(edge, acc);  // the keel or the deck within the waves' reach
  }

 private:
  // ζ and dζ/dx at x on still water: from the disc holding (x, 0) where there is one (its Taylor
  // polynomial of degree M costs less than the line's Chebyshev series of degree D, and a steep
  // side's crossings lie in its disc), else from the line; false outside both.
  bool elevation(double x, double& zeta, double& slope) const {
    if (const int patch = record_.patch_of(x, 0.0); patch >= 0) {
      Complex f, f_rate;
      record_.elevation_terms(poly_, patch, x, 0.0, f, f_rate);
      zeta = poly_.ramp * f.real();
      slope = -poly_.ramp * f_rate.imag();  // ∂/∂x = i ∂/∂z
      return true;
    }
    if (!(x >= record_.x_min() && x <= record_.x_max())) return false;
    record_.line_elevation(poly_, x, zeta, slope);
    return true;
  }

  // g = y − ζ along an edge and its s-derivatives, from the record along still water.
  struct LineGap {
    const RecordedEdges& self;
    const HullEdge& edge;
    void evaluate(double s, double& g, double& slope, double& curvature) const {
      double zeta = 0.0, zeta_x = 0.0, zeta_xx = 0.0;
      self.record_.line_elevation(self.poly_, edge.a.x() + s * edge.d.x(), zeta, zeta_x, zeta_xx);
      g = edge.a.y() + s * edge.d.y() - zeta;
      slope = edge.d.y() - edge.d.x() * zeta_x;
      curvature = -edge.d.x() * edge.d.x() * zeta_xx;
    }
    void evaluate(double s, double& g, double& slope) const {
      double curvature = 0.0;
      evaluate(s, g, slope, curvature);
    }
  };

  // Every crossing of an edge with the recorded surface (crossing_isolation.hpp), then its wetted
  // intervals. Start intervals about 2/k_max long along x, as the exact path's.
  bool crossings_along(const HullEdge& edge, EdgeMoments& acc) const {
    const LineGap gap{*this, edge};
    const double dx = std::abs(edge.d.x());
    const int count = start_interval_count(dx, record_.max_wave_number());
    std::array<CrossingInterval, kMaxStartIntervals> first;
    double g_prev = 0.0, slope_prev = 0.0, curvature_prev = 0.0;
    for (int j = 0; j <= count; ++j) {
      const double s = j == count ? 1.0 : static_cast<double>(j) / count;
      double g = 0.0, slope = 0.0, curvature = 0.0;
      gap.evaluate(s, g, slope, curvature);
      if (j > 0) first[static_cast<std::size_t>(j - 1)] = {static_cast<double>(j - 1) / count, s, g_prev, g, slope_prev, slope, curvature_prev, curvature};
      g_prev = g;
      slope_prev = slope;
      curvature_prev = curvature;
    }
    const double t = poly_.time, ramp = poly_.ramp;
    const CrossingBounds bounds{std::abs(edge.d.y()) + dx * record_.slope_bound(t, ramp), dx * dx * record_.curvature_bound(t, ramp),
                                dx * dx * dx * record_.third_derivative_bound(t, ramp)};
    WaterlineCrossings crossings;
    crossings.wet_at_start = first[0].g_lo < 0.0;
    isolate_crossings(gap, first.data(), count, bounds, crossings);
    if (crossings.truncated) return false;
    bool wet = crossings.wet_at_start;
    double wet_start = 0.0;
    for (int i = 0; i < crossings.count; ++i) {
      const double s = crossings.s[static_cast<std::size_t>(i)];
      if (wet && !wetted(edge, wet_start, s, acc)) return false;
      if (!wet) wet_start = s;
      wet = !wet;
    }
    return !wet || wetted(edge, wet_start, 1.0, acc);
  }

  // The root of g in [s_low, s_high]: Newton from the still-water point, kept inside the bracket. An
  // end that is the bound's level (not clamped to the edge's end) has a known sign — wet at y = −bound,
  // dry at y = +bound — and is not evaluated; a clamped end is, and when both ends have one sign the
  // side is wet or dry up to the clipped end.
  bool surface_crossing(const HullEdge& edge, double s_low, double s_high, double& root) const {
    const auto gap = [&](double s, double& g, double& g_rate) {
      double zeta = 0.0, slope = 0.0;
      if (!elevation(edge.a.x() + s * edge.d.x(), zeta, slope)) return false;
      g = edge.a.y() + s * edge.d.y() - zeta;
      g_rate = edge.d.y() - edge.d.x() * slope;
      return true;
    };
    const auto sign_at = [&](double s, bool clamped, double known, double& g) {
      double g_rate = 0.0;
      if (!clamped) {
        g = known;
        return true;
      }
      return gap(s, g, g_rate);
    };
    const double at_low_level = (-bound_ - edge.a.y()) / edge.d.y(), at_high_level = (bound_ - edge.a.y()) / edge.d.y();
    double g_wet = 0.0, g_dry = 0.0;  // g at s_low (wet side) and s_high (dry side)
    if (!sign_at(s_low, s_low != at_low_level, -1.0, g_wet) || !sign_at(s_high, s_high != at_high_level, 1.0, g_dry))
      return false;
    if ((g_wet < 0.0) == (g_dry < 0.0)) {  // no crossing inside: wet or dry up to the clipped end
      root = ((g_wet < 0.0) == (edge.d.y() > 0.0)) ? std::max(s_low, s_high) : std::min(s_low, s_high);
      return true;
    }
    // Bracket [lo, hi] with lo on the side of g's sign at s_low.
    double lo = std::min(s_low, s_high), hi = std::max(s_low, s_high);
    const bool lo_wet = (lo == s_low) == (g_wet < 0.0);
    double s = std::clamp(-edge.a.y() / edge.d.y(), lo, hi);
    for (int iteration = 0; iteration < max_root_iterations; ++iteration) {
      double g = 0.0, g_rate = 0.0;
      if (!gap(s, g, g_rate)) return false;
      if (g == 0.0) break;
      ((g < 0.0) == lo_wet ? lo : hi) = s;
      double next = s - g / g_rate;
      const bool newton = next > lo && next < hi;
      if (!newton) next = 0.5 * (lo + hi);
      const bool done = (newton && std::abs(next - s) <= root_tolerance) || hi - lo <= root_tolerance;
      s = next;
      if (done) break;
    }
    root = s;
    return true;
  }

  // The wetted interval [s0, s1], split at still water.
  bool wetted(const HullEdge& edge, double s0, double s1, EdgeMoments& acc) const {
    if (!(s1 > s0)) return true;
    acc.wetted_length += (s1 - s0) * edge.length;
    double cuts[3] = {s0, s1, s1};
    int pieces = 1;
    if (edge.d.y() != 0.0) {
      const double s_still = -edge.a.y() / edge.d.y();
      if (s_still > s0 && s_still < s1) {
        cuts[1] = s_still;
        cuts[2] = s1;
        pieces = 2;
      }
    }
    for (int i = 0; i < pieces; ++i) {
      const double lo = cuts[i], hi = cuts[i + 1];
      const bool airy = edge.a.y() + 0.5 * (lo + hi) * edge.d.y() <= 0.0;
      PieceIntegrals piece = hydrostatic_piece(edge, lo, hi - lo);
      if (!(airy ? add_submerged(edge, lo, hi, piece) : add_crest(edge, lo, hi, piece))) return false;
      add_piece(edge, g1_, lo, piece, acc);
    }
    return true;
  }

  bool antiderivatives(const HullEdge& edge, double s, Complex& g, Complex& h) const {
    const double x = edge.a.x() + s * edge.d.x();
    const double y = edge.a.y() + s * edge.d.y();
    const int patch = record_.patch_of(x, y);
    if (patch >= 0) {
      record_.antiderivatives(poly_, patch, x, y, g, h);
      return true;
    }
    // Outside the discs (a keel come out of the water between its corners, a corner beyond the
    // motion range): G and H at this one point by the component sums, O(components) for this point only.
    ComponentPhasors phasors(wave_, Complex(y, x), poly_.time);
    const std::vector<WaveComponent>& components = wave_.components();
    const std::vector<Complex>& amplitudes = wave_.complex_amplitudes();
    g = 0.0;
    h = 0.0;
    for (std::size_t n = 0; n < components.size(); ++n) {
      const Complex term = times(amplitudes[n], phasors.next());
      const double inverse_k = 1.0 / components[n].wave_number;
      g += inverse_k * term;
      h += (inverse_k * inverse_k) * term;
    }
    return true;
  }

  // Below still water: ∫F = (G1 − G0)/w, ∫uF = h G1/w − (H1 − H0)/w², w = d_y + i d_x.
  bool add_submerged(const HullEdge& edge, double s0, double s1, PieceIntegrals& piece) const {
    Complex g0, h0, g1, h1;
    if (!antiderivatives(edge, s0, g0, h0) || !antiderivatives(edge, s1, g1, h1)) return false;
    const Complex w(edge.d.y(), edge.d.x()), inverse = 1.0 / w;
    const double h = s1 - s0;
    piece.j0 += poly_.ramp * ((g1 - g0) * inverse).real();
    piece.j1 += poly_.ramp * (h * g1 * inverse - (h1 - h0) * inverse * inverse).real();
    return true;
  }

  // Above still water, below the crest: ζ(x(s)) − y; the wave's part ∫ζ along z = i x(s).
  bool add_crest(const HullEdge& edge, double s0, double s1, PieceIntegrals& piece) const {
    const double h = s1 - s0;
    const double x0 = edge.a.x() + s0 * edge.d.x(), x1 = edge.a.x() + s1 * edge.d.x();
    if (std::min(x0, x1) < record_.x_min() || std::max(x0, x1) > record_.x_max()) return false;
    if (std::abs(edge.d.x()) * h >= crest_quadrature_span) {
      // ∫₀ʰ ζ du = (Z₁(x1) − Z₁(x0))/d_x, ∫₀ʰ u ζ du = (h Z₁(x1) − (Z₂(x1) − Z₂(x0))/d_x)/d_x (ramp included).
      double first0 = 0.0, second0 = 0.0, first1 = 0.0, second1 = 0.0;
      record_.line_antiderivatives(poly_, x0, first0, second0);
      record_.line_antiderivatives(poly_, x1, first1, second1);
      const double inverse = 1.0 / edge.d.x();
      piece.j0 += (first1 - first0) * inverse;
      piece.j1 += (h * first1 - (second1 - second0) * inverse) * inverse;
      return true;
    }
    static const hydro::GaussRule& rule = hydro::gauss_legendre(crest_quadrature_points);
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
      const double u = 0.5 * h * (1.0 + rule.nodes[q]), weight = 0.5 * h * rule.weights[q];
      double zeta = 0.0, slope = 0.0;
      if (!elevation(edge.a.x() + (s0 + u) * edge.d.x(), zeta, slope)) return false;
      piece.j0 += weight * zeta;
      piece.j1 += weight * u * zeta;
    }
    return true;
  }

  const IncidentWaveRecord& record_;
  const WaveField& wave_;
  const WavePolynomials& poly_;
  Eigen::Vector2d g1_;
  double bound_, slope_;
};

// Corners and still-water points of one side (fore or aft) at the extremes of the motion range.
template <class Visit>
void visit_side(const BoxHullSection& hull, double g1_height, const HullMotionRange& range, bool fore, Visit&& visit) {
  const double side_x = fore ? hull.fore_x : hull.aft_x;
  for (const double surge : {-range.surge, range.surge})
    for (const double heave : {-range.heave, range.heave})
      for (const double pitch : {-range.pitch, range.pitch}) {
        const double c = std::cos(pitch), s = std::sin(pitch);
        const Eigen::Vector2d keel(surge + c * side_x - s * hull.keel_y, g1_height + heave + s * side_x + c * hull.keel_y);
        const Eigen::Vector2d deck(surge + c * side_x - s * hull.deck_y, g1_height + heave + s * side_x + c * hull.deck_y);
        visit(keel.x(), keel.y());
        visit(deck.x(), 0.0);
        if ((keel.y() < 0.0) != (deck.y() < 0.0)) {
          const double at = keel.y() / (keel.y() - deck.y());
          visit(keel.x() + at * (deck.x() - keel.x()), 0.0);
        }
      }
}

}  // namespace

std::vector<WavePatch> box_hull_patches(const BoxHullSection& hull, double g1_height, const HullMotionRange& range) {
  std::vector<WavePatch> patches;
  for (const bool fore : {false, true}) {
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    visit_side(hull, g1_height, range, fore, [&](double x, double y) {
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, std::min(y, 0.0));
    });
    const double half_x = 0.5 * (x_hi - x_lo), half_y = 0.5 * (y_hi - y_lo);
    patches.push_back({0.5 * (x_lo + x_hi), 0.5 * (y_lo + y_hi), 1.001 * std::hypot(half_x, half_y) + 1e-6});
  }
  return patches;
}

void box_hull_x_range(const BoxHullSection& hull, double g1_height, const HullMotionRange& range, double& x_min,
                      double& x_max) {
  x_min = INFINITY;
  x_max = -INFINITY;
  for (const bool fore : {false, true})
    visit_side(hull, g1_height, range, fore, [&](double x, double) {
      x_min = std::min(x_min, x);
      x_max = std::max(x_max, x);
    });
}

std::optional<HullLoad> recorded_hull_pressure_load(const BoxHullSection& hull, const IncidentWaveRecord& record,
                                                    const WaveField& wave, WavePolynomials& workspace, double ramp, double water_density,
                                                    double gravity, const Eigen::Vector2d& g1_position, double pitch,
                                                    double t) {
  if (!(t >= 0.0 && t <= record.duration())) return std::nullopt;
  if (!g1_position.allFinite() || !std::isfinite(pitch)) return std::nullopt;  // the exact path names the pose
  if (ramp == 0.0) return hull_pressure_load(hull, nullptr, water_density, gravity, g1_position, pitch, t);  // not yet ramped in
  record.at(t, ramp, workspace);
  const RecordedEdges edges(record, wave, workspace, g1_position);
  const double rho_g = water_density * gravity;
  HullLoad load;
  for (const HullEdge& edge : hull_edges(hull, g1_position, pitch)) {
    EdgeMoments moments;
    if (!edges.moments(edge, moments)) return std::nullopt;
    add_edge_load(hull, edge, moments, rho_g, load);
  }
  return load;
}

}  // namespace ffrf::sea
