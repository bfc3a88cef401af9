// Cubic interpolating splines for keyframed animation (paper §3.2: "its entire trajectory through the
// animation computed using spline interpolation"). We use C² cubic splines in the second-derivative
// (moment) form: natural ends when the animation plays once, periodic with period 1 when it loops, so a
// looping element has no kink where t = 1 meets t = 0. Values are plain numbers, so a rotation keyed as
// 0°, 360°, 720° really turns twice instead of being folded back to one angle.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "animpak/animation.hpp"
#include "animpak/error.hpp"

namespace animpak {

namespace {

std::string key_message(std::size_t i, const std::string& what) {
  std::ostringstream out;
  out << "[" << i << "]" << what;
  return out.str();
}

// Moments M_i (second derivatives at the keys) of the C² spline through (t_i, v_i). `loop`: the keys
// repeat with period 1 and the wrap interval [t_{n-1}, t_0 + 1] is one more spline piece.
std::vector<double> spline_moments(const std::vector<double>& t, const std::vector<double>& v, bool loop) {
  const int n = static_cast<int>(t.size());
  std::vector<double> moments(t.size(), 0.0);
  if (n < 3 && !loop) return moments;  // two keys, natural ends: the straight line, no overshoot
  if (n < 2) return moments;
  auto h = [&](int i) { return i + 1 < n ? t[i + 1] - t[i] : t[0] + 1.0 - t[n - 1]; };
  auto slope = [&](int i) { return ((i + 1 < n ? v[i + 1] : v[0]) - v[i]) / h(i); };
  // Dense solve: key counts are small (a handful per channel), and with two periodic keys both
  // neighbours of a key are the same key, which the += below accumulates correctly.
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    const bool end = !loop && (i == 0 || i == n - 1);
    if (end) {
      a(i, i) = 1.0;  // natural end: zero curvature
      continue;
    }
    const int prev = (i + n - 1) % n, next = (i + 1) % n;
    const double h0 = h(prev), h1 = h(i);
    a(i, prev) += h0;
    a(i, i) += 2.0 * (h0 + h1);
    a(i, next) += h1;
    b(i) = 6.0 * (slope(i) - slope(prev));
  }
  const Eigen::VectorXd m = a.partialPivLu().solve(b);
  for (int i = 0; i < n; ++i) moments[i] = m(i);
  return moments;
}

}  // namespace

Spline::Spline(std::vector<double> times, std::vector<double> values, bool loop)
    : times_(std::move(times)), values_(std::move(values)), loop_(loop) {
  if (times_.empty()) throw InputError("needs at least one key");
  if (times_.size() != values_.size()) throw InputError("one value per key time is needed");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || times_[i] < 0.0 || times_[i] > 1.0) {
      std::ostringstream out;
      out << ".t = " << times_[i] << ": expected a time in [0, 1]";
      throw InputError(key_message(i, out.str()));
    }
    if (!std::isfinite(values_[i])) throw InputError(key_message(i, ": value is not a finite number"));
    if (i > 0 && !(times_[i] > times_[i - 1])) {
      std::ostringstream out;
      out << ".t = " << times_[i] << ": must be greater than the previous key's t (" << times_[i - 1]
          << "); list keys in strictly increasing time";
      throw InputError(key_message(i, out.str()));
    }
  }
  if (loop_ && times_.size() > 1 && times_.back() == 1.0) {
    // t = 1 is t = 0 of the next loop: a key there is the t = 0 key again (or stands in for it).
    const std::size_t last = times_.size() - 1;
    if (times_.front() == 0.0) {
      if (values_.back() != values_.front()) {
        std::ostringstream out;
        out << ": a looping animation's key at t = 1 must equal its key at t = 0 (" << values_.back() << " vs "
            << values_.front() << "); make them equal, drop the t = 1 key, or set loop to false";
        throw InputError(key_message(last, out.str()));
      }
      times_.pop_back();
      values_.pop_back();
    } else {
      times_.insert(times_.begin(), 0.0);
      values_.insert(values_.begin(), values_.back());
      times_.pop_back();
      values_.pop_back();
    }
  }
  moments_ = spline_moments(times_, values_, loop_);
}

double Spline::operator()(double t) const {
  const std::size_t n = times_.size();
  if (n == 1) return values_[0];
  std::size_t i = 0;  // piece [times_[i], times_[i] + h] ending at key j
  std::size_t j = 1;
  double h = 0.0;
  if (loop_) {
    t -= std::floor(t);
    if (t < times_[0]) t += 1.0;  // inside the wrap piece [t_{n-1}, t_0 + 1]
    if (t >= times_[n - 1]) {
      i = n - 1;
      j = 0;
      h = times_[0] + 1.0 - times_[n - 1];
    }
  } else {
    if (t <= times_[0]) return values_[0];
    if (t >= times_[n - 1]) return values_[n - 1];
  }
  if (h == 0.0) {
    // Last key at or before t; upper_bound keeps a key time itself on the piece it starts.
    i = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    j = i + 1;
    h = times_[j] - times_[i];
  }
  const double b = (t - times_[i]) / h;
  const double a = 1.0 - b;
  if (b == 0.0) return values_[i];  // exactly on a key: no rounding from the cubic terms
  return a * values_[i] + b * values_[j] +
         ((a * a * a - a) * moments_[i] + (b * b * b - b) * moments_[j]) * (h * h) / 6.0;
}

}  // namespace animpak
