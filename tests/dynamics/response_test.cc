// Frequency estimators (dynamics/response.h) against closed-form signals.
#include "dynamics/response.h"

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace tbridge {
namespace {

constexpr double kPi = std::numbers::pi;

// y(t) = offset + sum of a_k sin(w_k t + phi_k) exp(-zeta_k w_k t), sampled at t = k dt.
struct Tone {
  double amplitude, omega, phase, zeta = 0;
};
Eigen::VectorXd Signal(const std::vector<Tone>& tones, double dt, int samples, double offset = 0) {
  Eigen::VectorXd y = Eigen::VectorXd::Constant(samples, offset);
  for (int k = 0; k < samples; ++k) {
    const double t = k * dt;
    for (const Tone& tone : tones) {
      y(k) += tone.amplitude * std::sin(tone.omega * t + tone.phase) *
              std::exp(-tone.zeta * tone.omega * t);
    }
  }
  return y;
}

TEST_CASE("FFT matches a direct DFT", "[dynamics][response]") {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  const int n = 64;
  std::vector<std::complex<double>> x(n);
  for (auto& v : x) v = {normal(rng), normal(rng)};
  std::vector<std::complex<double>> fast = x;
  Fft(fast);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    std::complex<double> direct = 0;
    for (int j = 0; j < n; ++j) direct += x[j] * std::polar(1.0, -2 * kPi * k * j / n);
    worst = std::max(worst, std::abs(direct - fast[k]));
  }
  CHECK(worst < 1e-12);  // O(n eps log n) round-off on O(sqrt n) values
  std::vector<std::complex<double>> bad(12);
  CHECK_THROWS_AS(Fft(bad), std::invalid_argument);
}

TEST_CASE("Dominant frequency of a sinusoid between bins", "[dynamics][response]") {
  // 1 s record, 1000 samples: FFT bin 1 Hz; 53.3 rad/s = 8.483 Hz sits between bins, with an
  // offset the mean removal must not turn into a bias.
  const double dt = 1e-3, omega = 53.3;
  const Eigen::VectorXd y = Signal({{0.02, omega, 0.4}}, dt, 1000, -0.1);
  const FrequencyEstimate e = DominantFrequency(y, dt);
  // The least-squares fit is exact for a clean sinusoid; 1e-4 is the acceptance bound.
  CHECK(e.omega_rad_s == Approx(omega).epsilon(1e-4));
  CHECK(e.frequency_hz == Approx(omega / (2 * kPi)).epsilon(1e-4));
  CHECK(e.period_s == Approx(2 * kPi / omega).epsilon(1e-4));
  CHECK(e.amplitude == Approx(0.02).epsilon(1e-4));
  // Without refinement the padded grid (1/8 Hz) is all there is: error up to half its step.
  SpectrumOptions coarse;
  coarse.refine = false;
  const FrequencyEstimate g = DominantFrequency(y, dt, coarse);
  CHECK(std::abs(g.frequency_hz - omega / (2 * kPi)) <= 0.5 * 1000.0 / 8192 + 0.01);
  CHECK(std::abs(g.frequency_hz - omega / (2 * kPi)) > 1e-4 * omega / (2 * kPi));
}

TEST_CASE("A small oscillation on a large offset keeps its precision", "[dynamics][response]") {
  // Amplitude 1e-7 on an offset of 0.5 (a displacement recorded as a position): the fit runs
  // on the centred record, so the result is as exact as without the offset. 1e-6 relative is
  // far above the fit's round-off (~1e-10 here) and far below the 5.8e-4 bias an uncentred
  // fit shows on this record.
  const double dt = 1e-4, omega = 71.0;
  for (int samples : {8000, 8001}) {
    const Eigen::VectorXd y = Signal({{1e-7, omega, 0.3}}, dt, samples, 0.5);
    INFO(samples << " samples");
    CHECK(DominantFrequency(y, dt).omega_rad_s == Approx(omega).epsilon(1e-6));
  }
}

TEST_CASE("The stronger of two sinusoids is dominant", "[dynamics][response]") {
  const double dt = 2e-3;
  const Eigen::VectorXd y = Signal({{1.0, 81.7, 0.1}, {0.6, 229.3, 1.3}}, dt, 1500);
  CHECK(DominantFrequency(y, dt).omega_rad_s == Approx(81.7).epsilon(1e-3));
  // Restricting the band to above 20 Hz finds the weaker tone.
  SpectrumOptions band;
  band.min_hz = 20;
  CHECK(DominantFrequency(y, dt, band).omega_rad_s == Approx(229.3).epsilon(1e-3));
  // Tolerance 1e-3: the other tone's leakage into the fit is what is left.
}

TEST_CASE("A decaying sinusoid gives its damped frequency", "[dynamics][response]") {
  const double dt = 1e-3, omega = 100.8, zeta = 0.01;
  const double damped = omega * std::sqrt(1 - zeta * zeta);
  const Eigen::VectorXd y = Signal({{0.01, damped, 0.0, zeta * omega / damped}}, dt, 2000);
  // The decay widens the peak but leaves it centred: 1e-3 covers the envelope's asymmetry.
  CHECK(DominantFrequency(y, dt).omega_rad_s == Approx(damped).epsilon(1e-3));
  CHECK(MeanPeriodFromCrossings(y, dt).omega_rad_s == Approx(damped).epsilon(1e-3));
}

TEST_CASE("Estimators stand up to noise", "[dynamics][response]") {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  const double dt = 5e-4, omega = 64.0;
  const Eigen::VectorXd clean = Signal({{1.0, omega, 2.0}}, dt, 4000);
  Eigen::VectorXd white(clean.size());
  for (Eigen::Index k = 0; k < white.size(); ++k) white(k) = normal(rng);
  // Strong white noise, RMS 0.3 of the amplitude, over ~40 cycles: the spectral estimate's
  // spread is ~1e-4 (Cramer-Rao), so 1e-3 leaves margin.
  CHECK(DominantFrequency(clean + 0.3 * white, dt).omega_rad_s == Approx(omega).epsilon(1e-3));
  // Crossings need the noise well inside the hysteresis band (RMS 0.05 vs band 0.35): only
  // the jitter of the first and last crossing remains, ~noise / slope / record = 4e-5.
  const Eigen::VectorXd mild = clean + 0.05 * white;
  CHECK(MeanPeriodFromCrossings(mild, dt).omega_rad_s == Approx(omega).epsilon(1e-3));
  // Without hysteresis the noise near the mean adds spurious crossings.
  CrossingOptions none;
  none.hysteresis = 0;
  CHECK(MeanPeriodFromCrossings(mild, dt, none).omega_rad_s > 1.2 * omega);
}

TEST_CASE("Spectral and crossing estimators agree on a clean sinusoid", "[dynamics][response]") {
  const double dt = 1e-4, omega = 142.5;
  const Eigen::VectorXd y = Signal({{0.3, omega, 0.7}}, dt, 12345, 2.0);
  const FrequencyEstimate spectral = DominantFrequency(y, dt);
  const FrequencyEstimate crossings = MeanPeriodFromCrossings(y, dt);
  // Crossing times are linearly interpolated: error ~ (omega dt)^2 / 8 per crossing.
  CHECK(crossings.omega_rad_s == Approx(spectral.omega_rad_s).epsilon(1e-5));
  CHECK(crossings.amplitude == Approx(0.3).epsilon(1e-3));  // sampled extremes
  CHECK(crossings.cycles == Approx(std::floor(12345 * dt * omega / kPi) / 2).margin(0.51));
}

TEST_CASE("Deck frequency sums the deck nodes over the first second", "[dynamics][response]") {
  // Two deck nodes in antiphase on a 40 rad/s mode cancel in the sum; the in-phase 60 rad/s
  // part remains. After t = 1 s a large 200 rad/s tail must be ignored.
  const double dt = 1e-3;
  const int samples = 3000;
  Eigen::MatrixXd deck(samples, 2);
  deck.col(0) = Signal({{1.0, 40.0, 0.0}, {0.3, 60.0, 0.5}}, dt, samples);
  deck.col(1) = Signal({{-1.0, 40.0, 0.0}, {0.3, 60.0, 0.5}}, dt, samples);
  for (int k = 1001; k < samples; ++k) deck(k, 0) += 10 * std::sin(200.0 * k * dt);
  // 1 s holds ~10 cycles; the fit is exact for the clean sum.
  CHECK(DeckFrequency(deck, dt).omega_rad_s == Approx(60.0).epsilon(1e-4));
  CHECK(DeckFrequency(deck, dt, 3.0).omega_rad_s == Approx(200.0).epsilon(1e-3));
  CHECK_THROWS_AS(DeckFrequency(Eigen::MatrixXd(), dt), std::invalid_argument);
}

TEST_CASE("Estimators reject unusable records", "[dynamics][response]") {
  const Eigen::VectorXd flat = Eigen::VectorXd::Constant(100, 3.0);
  CHECK_THROWS_WITH(DominantFrequency(flat, 1e-3), Catch::Contains("constant"));
  CHECK_THROWS_AS(DominantFrequency(Eigen::VectorXd::Ones(1), 1e-3), std::invalid_argument);
  CHECK_THROWS_AS(DominantFrequency(Signal({{1, 10, 0}}, 1e-3, 100), 0.0), std::invalid_argument);
  Eigen::VectorXd nan = Signal({{1, 10, 0}}, 1e-3, 100);
  nan(5) = std::nan("");
  CHECK_THROWS_AS(DominantFrequency(nan, 1e-3), std::invalid_argument);
  // Half a period has one crossing only.
  CHECK_THROWS_WITH(MeanPeriodFromCrossings(Signal({{1, kPi, 0.5}}, 1e-3, 1000), 1e-3),
                    Catch::Contains("need 3"));
}

TEST_CASE("The trend share of a ramp is 1, of a sine of N periods 6 / (pi^2 N^2)",
          "[dynamics][response]") {
  const Eigen::VectorXd ramp = Eigen::VectorXd::LinSpaced(1001, 0.0, 0.2);
  CHECK(TrendShare(ramp) == Approx(1.0).epsilon(1e-12));  // exactly a line; 1e-12 for rounding
  for (const double periods : {2.0, 5.0}) {
    // The continuous closed form: cov(t, sin(2 pi N t)) = -1/(2 pi N), var t = 1/12, var sin
    // = 1/2 over [0, 1]. 1001 samples sum to the integral within O(1/n): 0.3 % here, so 1 %.
    const Eigen::VectorXd sine = Signal({{1.0, 2 * kPi * periods, 0.0}}, 1e-3, 1001);
    CHECK(TrendShare(sine) == Approx(6 / (kPi * kPi * periods * periods)).epsilon(0.01));
  }
  CHECK(TrendShare(Eigen::VectorXd::Constant(10, 3.0)) == 0);  // no variance to explain
}

TEST_CASE("A frequency is read only from an oscillation of at least two periods",
          "[dynamics][response]") {
  const double dt = 1e-3;
  // 5 periods of 5 Hz over the 1 s record, on an offset: its frequency. The least-squares
  // refinement is exact for a clean sinusoid, so 1e-4 as above; the FFT grid alone would be
  // within half its step, 1 / (2 x 8 x 1 s) = 0.0625 Hz.
  const FrequencyReading five =
      MeasureFrequency(Signal({{0.02, 2 * kPi * 5.0, 0.3}}, dt, 1001, -0.1), dt);
  INFO(five.note);
  REQUIRE(five.estimate);
  CHECK(five.estimate->frequency_hz == Approx(5.0).epsilon(1e-4));
  CHECK(five.note.empty());
  // 1.5 periods: one swing and a half tell no frequency.
  const FrequencyReading short_record =
      MeasureFrequency(Signal({{0.02, 2 * kPi * 1.5, 0.3}}, dt, 1001), dt);
  CHECK_FALSE(short_record.estimate);
  CHECK_THAT(short_record.note, Catch::Contains("periods") && Catch::Contains("fewer than 2"));
  // A pure ramp, as a deck sinking under a slowly applied load: a drift, whatever its spectrum.
  const FrequencyReading ramp = MeasureFrequency(Eigen::VectorXd::LinSpaced(1001, 0.0, -0.5), dt);
  CHECK_FALSE(ramp.estimate);
  CHECK_THAT(ramp.note, Catch::Contains("drift") && Catch::Contains("100 %"));
  // A constant record, whose mean removal leaves only last-place noise: nothing moves.
  const FrequencyReading still = MeasureFrequency(Eigen::VectorXd::Constant(1001, 0.1), dt);
  CHECK_FALSE(still.estimate);
  CHECK_THAT(still.note, Catch::Contains("constant"));
}

}  // namespace
}  // namespace tbridge
