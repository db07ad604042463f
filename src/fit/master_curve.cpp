#include "fit/master_curve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "model/numerics/number_text.hpp"

namespace punchsweep::fit {
namespace {

/// An isotherm in log-log, sorted by abscissa, its ordinate made monotone (a running
/// maximum where it rises overall, a running minimum where it falls).
struct LogCurve {
  std::vector<double> lx, ly;
  double lo() const { return *std::min_element(ly.begin(), ly.end()); }
  double hi() const { return *std::max_element(ly.begin(), ly.end()); }
  /// log10 x where the curve first reaches log10 y = v (v within [lo, hi]), and the
  /// slope d log10 y / d log10 x of the segment there (0 on a flat one).
  double x_at(double v, double* slope) const {
    *slope = 0.0;
    for (std::size_t k = 0; k + 1 < ly.size(); ++k) {
      const double a = ly[k], b = ly[k + 1];
      if (a == b) {
        if (v == a) return lx[k];
        continue;
      }
      if ((v - a) * (v - b) <= 0.0) {
        *slope = (b - a) / (lx[k + 1] - lx[k]);
        return lx[k] + (v - a) / (b - a) * (lx[k + 1] - lx[k]);
      }
    }
    return ly.front() == v ? lx.front() : lx.back();
  }
};

LogCurve log_curve(const Isotherm& iso) {
  std::vector<std::size_t> order(iso.x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return iso.x[a] < iso.x[b]; });
  LogCurve c;
  for (const std::size_t k : order) {
    c.lx.push_back(std::log10(iso.x[k]));
    c.ly.push_back(std::log10(iso.y[k]));
  }
  // Monotone by isotonic regression (pool adjacent violators: each run that breaks the
  // order becomes its mean), which noise leaves unbiased where a running extreme would
  // ratchet upward on a plateau.
  const bool rising = c.ly.back() >= c.ly.front();
  std::vector<double> value, weight;
  std::vector<std::size_t> count;
  for (const double y : c.ly) {
    value.push_back(rising ? y : -y);
    weight.push_back(1.0);
    count.push_back(1);
    while (value.size() > 1 && value[value.size() - 2] > value.back()) {
      const std::size_t k = value.size() - 2;
      value[k] = (value[k] * weight[k] + value.back() * weight.back()) / (weight[k] + weight.back());
      weight[k] += weight.back();
      count[k] += count.back();
      value.pop_back();
      weight.pop_back();
      count.pop_back();
    }
  }
  std::size_t at = 0;
  for (std::size_t b = 0; b < value.size(); ++b) {
    for (std::size_t j = 0; j < count[b]; ++j) c.ly[at++] = rising ? value[b] : -value[b];
  }
  return c;
}

std::string degc(double t) { return model::number_text(t, 6) + " degC"; }

/// Least squares of L ~ p g + c over the isotherms: (p, c, sum of squares).
struct LineFit {
  double p, c, sse;
};
LineFit fit_line(const std::vector<double>& g, const std::vector<double>& L) {
  const auto n = static_cast<Eigen::Index>(g.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    A(i, 0) = g[static_cast<std::size_t>(i)];
    A(i, 1) = 1.0;
    b(i) = L[static_cast<std::size_t>(i)];
  }
  const Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
  return {x(0), x(1), (A * x - b).squaredNorm()};
}

std::vector<double> wlf_basis(const std::vector<double>& T, double T_ref, double C2) {
  std::vector<double> g;
  for (const double t : T) g.push_back(-(t - T_ref) / (C2 + t - T_ref));
  return g;
}

/// WLF's C1, C2 and zero by least squares: C2 over a logarithmic grid above its lower
/// bound, then golden section between the best point's neighbours.
model::TemperatureShift fit_wlf(const std::vector<double>& T, const std::vector<double>& L, double T_ref, double* zero) {
  const double lower = std::max(0.0, T_ref - T.front());
  const double a = std::log(lower + 0.1), b = std::log(kWlfC2Max);
  const auto sse_at = [&](double log_c2) {
    const LineFit f = fit_line(wlf_basis(T, T_ref, std::exp(log_c2)), L);
    return f.p > 0.0 ? f.sse : std::numeric_limits<double>::infinity();
  };
  constexpr int kGrid = 400;
  int best = -1;
  double best_sse = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kGrid; ++k) {
    const double s = sse_at(a + (b - a) * k / kGrid);
    if (s < best_sse) {
      best_sse = s;
      best = k;
    }
  }
  if (best < 0) {
    throw std::invalid_argument("the measured shifts do not fall with temperature as WLF needs (no C1 > 0 fits them); "
                                "give the law (--C1, --C2) or try --shift arrhenius");
  }
  double lo = a + (b - a) * std::max(0, best - 1) / kGrid, hi = a + (b - a) * std::min(kGrid, best + 1) / kGrid;
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 80; ++it) {
    const double m1 = hi - r * (hi - lo), m2 = lo + r * (hi - lo);
    if (sse_at(m1) <= sse_at(m2)) hi = m2; else lo = m1;
  }
  const double C2 = std::exp(0.5 * (lo + hi));
  const LineFit f = fit_line(wlf_basis(T, T_ref, C2), L);
  model::TemperatureShift law;
  law.kind = model::TemperatureShift::Kind::wlf;
  law.T_ref = T_ref;
  law.C1 = f.p;
  law.C2 = C2;
  *zero = f.c;
  return law;
}

model::TemperatureShift fit_arrhenius(const std::vector<double>& T, const std::vector<double>& L, double T_ref, double* zero) {
  std::vector<double> h;
  for (const double t : T) {
    h.push_back((1.0 / (t + model::kZeroCelsius) - 1.0 / (T_ref + model::kZeroCelsius)) / (model::kGasConstant * std::log(10.0)));
  }
  const LineFit f = fit_line(h, L);
  if (!(f.p > 0.0)) {
    throw std::invalid_argument("the measured shifts do not fall with temperature as Arrhenius needs (fitted E_a = " +
                                model::number_text(f.p, 6) + " J/mol is not > 0)");
  }
  model::TemperatureShift law;
  law.kind = model::TemperatureShift::Kind::arrhenius;
  law.T_ref = T_ref;
  law.E_a = f.p;
  *zero = f.c;
  return law;
}

}  // namespace

double overlap_shift(const Isotherm& lower, const Isotherm& upper) {
  const LogCurve a = log_curve(lower), b = log_curve(upper);
  const double lo = std::max(a.lo(), b.lo()), hi = std::min(a.hi(), b.hi());
  std::vector<double> values;
  for (const LogCurve* c : {&a, &b}) {
    for (const double v : c->ly) {
      if (v >= lo && v <= hi) values.push_back(v);
    }
  }
  if (!(hi > lo) || values.size() < 2) {
    throw std::invalid_argument("the isotherms at " + degc(lower.temperature) + " and " + degc(upper.temperature) +
                                " do not overlap in modulus (" + std::to_string(values.size()) +
                                " readings in common), so no shift lays one on the other; measure closer "
                                "temperatures or a wider frequency range, or give the shift law (--C1, --C2)");
  }
  // Each modulus gives a shift; noise of s in log10 y moves it by s / slope on each curve,
  // so each is weighted by 1 / (1/slope_a^2 + 1/slope_b^2): flat stretches say little.
  double sum = 0.0, weights = 0.0, plain = 0.0;
  for (const double v : values) {
    double sa = 0.0, sb = 0.0;
    const double d = a.x_at(v, &sa) - b.x_at(v, &sb);
    plain += d;
    if (sa != 0.0 && sb != 0.0) {
      const double w = 1.0 / (1.0 / (sa * sa) + 1.0 / (sb * sb));
      sum += w * d;
      weights += w;
    }
  }
  return weights > 0.0 ? sum / weights : plain / static_cast<double>(values.size());
}

MasterCurve build_master_curve(std::span<const Isotherm> isotherms, Abscissa abscissa, const ShiftRequest& request) {
  std::vector<Isotherm> iso(isotherms.begin(), isotherms.end());
  std::sort(iso.begin(), iso.end(), [](const Isotherm& p, const Isotherm& q) { return p.temperature < q.temperature; });
  MasterCurve m;
  for (const Isotherm& i : iso) m.temperatures.push_back(i.temperature);
  const std::size_t n = iso.size();
  if (request.law == ShiftRequest::Law::given) {
    m.law = request.given;
    for (const double t : m.temperatures) {
      if (!m.law->admits(t)) {
        throw std::invalid_argument("the isotherm at " + degc(t) + " is outside the given shift law's " + m.law->range());
      }
      m.law_log10_aT.push_back(m.law->log10_factor(t));
      m.measured_log10_aT.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    return m;
  }
  if (n == 1) {
    if (std::abs(m.temperatures[0] - request.T_ref) > 1e-9) {
      throw std::invalid_argument("one isotherm, at " + degc(m.temperatures[0]) +
                                  ", cannot be shifted to the reference temperature " + degc(request.T_ref) +
                                  ": give the shift law (--C1, --C2) or that temperature as the reference");
    }
    m.measured_log10_aT = {0.0};
    m.law_log10_aT = {0.0};
    return m;
  }
  const std::size_t needed = request.law == ShiftRequest::Law::wlf ? 3 : 2;
  if (n < needed) {
    throw std::invalid_argument(std::to_string(n) + " isotherms are too few to fit " +
                                (request.law == ShiftRequest::Law::wlf ? "WLF (C1, C2 and the zero: 3 or more)"
                                                                       : "Arrhenius (E_a and the zero: 2 or more)") +
                                "; give the law (--C1, --C2)");
  }
  // Offsets in log10 x from the isotherm nearest T_ref outward.
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(m.temperatures[i] - request.T_ref) < std::abs(m.temperatures[k] - request.T_ref)) k = i;
  }
  std::vector<double> D(n, 0.0);
  for (std::size_t j = k + 1; j < n; ++j) D[j] = D[j - 1] + overlap_shift(iso[j - 1], iso[j]);
  for (std::size_t j = k; j-- > 0;) D[j] = D[j + 1] - overlap_shift(iso[j], iso[j + 1]);
  std::vector<double> L(n);
  const double sign = abscissa == Abscissa::frequency ? 1.0 : -1.0;
  for (std::size_t i = 0; i < n; ++i) L[i] = sign * D[i];
  return fit_shift_law(m.temperatures, L, request);
}

MasterCurve fit_shift_law(const std::vector<double>& temperatures, const std::vector<double>& L,
                          const ShiftRequest& request) {
  MasterCurve m;
  m.temperatures = temperatures;
  const std::size_t n = temperatures.size();
  double zero = 0.0;
  m.law = request.law == ShiftRequest::Law::wlf ? fit_wlf(m.temperatures, L, request.T_ref, &zero)
                                                : fit_arrhenius(m.temperatures, L, request.T_ref, &zero);
  m.law->T_min = std::min(m.temperatures.front(), request.T_ref);
  m.law->T_max = std::max(m.temperatures.back(), request.T_ref);
  if (const std::string e = m.law->error(); !e.empty()) throw std::invalid_argument("the fitted " + e);
  double ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    m.measured_log10_aT.push_back(L[i] - zero);
    m.law_log10_aT.push_back(m.law->log10_factor(m.temperatures[i]));
    ss += std::pow(m.measured_log10_aT[i] - m.law_log10_aT[i], 2);
  }
  m.rms_log10 = std::sqrt(ss / static_cast<double>(n));
  return m;
}

}  // namespace punchsweep::fit
