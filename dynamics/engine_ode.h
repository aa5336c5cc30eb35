// The adapter from a dynamics engine (Class1System, ClassKSystem) to the integrators: it owns
// the engine's workspace and can hold the timed loads at one time for the stages of a step.
#pragma once

#include "dynamics/integrators.h"

namespace tbridge {

// Calls body.template operator()<D, Damped, Stabilised>() with the run-time dimension (2 or
// 3), damping and stabilisation as constants: one dispatch per evaluation picks the loop
// specialised for what the scene needs (velocity terms only with damping, the correction
// only when asked).
template <class Body>
inline void Specialise(int dim, bool damped, bool stabilised, Body&& body) {
  auto in_dim = [&]<int D>() {
    if (damped) {
      stabilised ? body.template operator()<D, true, true>()
                 : body.template operator()<D, true, false>();
    } else {
      stabilised ? body.template operator()<D, false, true>()
                 : body.template operator()<D, false, false>();
    }
  };
  dim == 2 ? in_dim.template operator()<2>() : in_dim.template operator()<3>();
}

// `System` provides state_size() and Derivative(t, y, dy, Workspace&); the workspace is
// made by MakeWorkspace(system), found next to the engine.
template <class System, class Workspace>
class EngineOde final : public OdeSystem {
 public:
  explicit EngineOde(const System& system) : system_(system), ws_(MakeWorkspace(system)) {}
  int size() const override { return system_.state_size(); }
  void Derivative(double t, const double* y, double* dy) override {
    system_.Derivative(hold_loads_ ? load_time_ : t, y, dy, ws_);
  }
  double DissipatedPower() const override { return ws_.damper_power; }
  // Evaluates the timed loads at `t` for every stage from now on. A fixed-step driver holds
  // them at each step's midpoint, so that a load switching on a step boundary is constant
  // within every step (a switch inside the stages of one step would cost O(dt) in energy).
  void HoldLoadsAt(double t) {
    hold_loads_ = true;
    load_time_ = t;
  }
  // The next evaluation also writes each string's geometry at its state to `out` (one per
  // model string; StringGeometry).
  void RecordStringsInNextEvaluation(const StringGeometry* out) { ws_.record_strings = out; }

 private:
  const System& system_;
  Workspace ws_;
  bool hold_loads_ = false;
  double load_time_ = 0;
};

}  // namespace tbridge
