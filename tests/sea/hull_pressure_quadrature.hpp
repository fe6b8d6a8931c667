// The second method for the closed-form hull pressure integral (sea/hull_pressure.cpp): the
// quadrature ffrf used before the closed form, kept here as an independent check. Each box edge is sampled
// `samples` times for sign changes of y − ζ, every change refined by bisection to 1e-13 in the edge
// parameter, each wetted interval split at y = 0 and into pieces ≤ 5 m integrated by 8-point
// Gauss–Legendre, with the pressure from WaveField::pressure point by point.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

#include "sea/hull_pressure.hpp"
#include "sea/wave_field.hpp"

namespace ffrf::sea::testing {

class QuadratureHullPressure {
 public:
  QuadratureHullPressure(const WaveField* wave, double density, double gravity, double t, int samples = 64)
      : wave_(wave), density_(density), gravity_(gravity), t_(t), samples_(samples) {}

  HullLoad load(const BoxHullSection& hull, const Eigen::Vector2d& g1, double pitch) const {
    const double c = std::cos(pitch), s = std::sin(pitch);
    const auto place = [&](double x, double y) { return Eigen::Vector2d(g1.x() + c * x - s * y, g1.y() + s * x + c * y); };
    const std::array<Eigen::Vector2d, 4> corner = {place(hull.aft_x, hull.keel_y), place(hull.fore_x, hull.keel_y),
                                                   place(hull.fore_x, hull.deck_y), place(hull.aft_x, hull.deck_y)};
    HullLoad out;
    for (std::size_t e = 0; e < 4; ++e) {
      const Eigen::Vector2d a = corner[e], d = corner[(e + 1) % 4] - a;
      Moments m;
      edge(a, d, g1, m);
      if (m.wetted_length == 0.0) continue;
      const Eigen::Vector2d n = Eigen::Vector2d(d.y(), -d.x()) / d.norm();
      out.force -= hull.width * m.p0 * n;
      out.moment -= hull.width * (m.p1.x() * n.y() - m.p1.y() * n.x());
      out.wetted_length += m.wetted_length;
    }
    return out;
  }

 private:
  struct Moments {
    double p0 = 0.0;
    Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
    double wetted_length = 0.0;
  };

  double pressure(const Eigen::Vector2d& r) const {
    if (wave_) return wave_->pressure(r.x(), r.y(), t_, density_);
    return r.y() < 0.0 ? -density_ * gravity_ * r.y() : 0.0;
  }
  bool wet(const Eigen::Vector2d& r) const { return r.y() < (wave_ ? wave_->elevation(r.x(), t_) : 0.0); }

  void piece(const Eigen::Vector2d& a, const Eigen::Vector2d& d, const Eigen::Vector2d& g1, double s0, double s1,
             Moments& m) const {
    static constexpr std::array<double, 4> node = {0.18343464249564980494, 0.52553240991632898582,
                                                   0.79666647741362673959, 0.96028985649753623168};
    static constexpr std::array<double, 4> weight = {0.36268378337836198297, 0.31370664587788728734,
                                                     0.22238103445337447054, 0.10122853629037625915};
    const double length = d.norm();
    const int count = std::max(1, static_cast<int>(std::ceil((s1 - s0) * length / 5.0)));
    const double h = (s1 - s0) / count;
    for (int j = 0; j < count; ++j) {
      const double mid = s0 + (j + 0.5) * h;
      for (std::size_t i = 0; i < node.size(); ++i) {
        for (const double sign : {-1.0, 1.0}) {
          const Eigen::Vector2d r = a + (mid + sign * 0.5 * h * node[i]) * d;
          const double w = weight[i] * 0.5 * h * length * pressure(r);
          m.p0 += w;
          m.p1 += w * (r - g1);
        }
      }
    }
  }

  void wetted(const Eigen::Vector2d& a, const Eigen::Vector2d& d, const Eigen::Vector2d& g1, double s0, double s1,
              Moments& m) const {
    if (!(s1 > s0)) return;
    m.wetted_length += (s1 - s0) * d.norm();
    if (d.y() != 0.0) {
      const double s_still = -a.y() / d.y();
      if (s_still > s0 && s_still < s1) {
        piece(a, d, g1, s0, s_still, m);
        piece(a, d, g1, s_still, s1, m);
        return;
      }
    }
    piece(a, d, g1, s0, s1, m);
  }

  void edge(const Eigen::Vector2d& a, const Eigen::Vector2d& d, const Eigen::Vector2d& g1, Moments& m) const {
    double prev_s = 0.0, wet_start = 0.0;
    bool prev_wet = wet(a);
    for (int i = 1; i <= samples_; ++i) {
      const double s = static_cast<double>(i) / samples_;
      const bool now = wet(a + s * d);
      if (now != prev_wet) {
        double lo = prev_s, hi = s;
        while (hi - lo > 1e-13) {
          const double mid = 0.5 * (lo + hi);
          (wet(a + mid * d) == prev_wet ? lo : hi) = mid;
        }
        const double root = 0.5 * (lo + hi);
        if (now) wet_start = root;
        else wetted(a, d, g1, wet_start, root, m);
      }
      prev_s = s;
      prev_wet = now;
    }
    if (prev_wet) wetted(a, d, g1, wet_start, 1.0, m);
  }

  const WaveField* wave_;
  double density_, gravity_, t_;
  int samples_;
};

}  // namespace ffrf::sea::testing
