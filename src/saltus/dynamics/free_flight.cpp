#include "saltus/dynamics/free_flight.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"

namespace saltus {

namespace {
/// More steps than this between two output times is a mistake (a flight of years), not a job.
constexpr double kMaxFreeFlightSteps = 1e8;
}  // namespace

void solve_free_root_acceleration(const BodyModel& model, BodyState<double>& state) {
  DynamicsData<double> data(model);
  JointState<double>& root = state.joints[0];
  const Eigen::Matrix3d r0 = root.q.toRotationMatrix();
  const Eigen::Vector3d v_body = r0.transpose() * state.root_velocity;
  // Choose the root motion whose spatial acceleration (gravity offset included) is zero; the
  // root wrench then equals the bias term alone.
  root.alpha.setZero();
  state.root_acceleration = gravity() + r0 * root.omega.cross(v_body);
  inverse_dynamics(model, data, state);
  const Vec6<double> bias = data.joint_wrench[0];
  const Mat6<double> ic = composite_inertia_at_root(model, data);
  const Vec6<double> a0 = -ic.ldlt().solve(bias);
  root.alpha = a0.head<3>();
  state.root_acceleration = r0 * (a0.tail<3>() + root.omega.cross(v_body)) + gravity();
}

void set_root_from_momentum(const BodyModel& model, const Eigen::Vector3d& com_position,
                            const Eigen::Vector3d& com_velocity,
                            const Eigen::Vector3d& angular_momentum, BodyState<double>& state) {
  DynamicsData<double> data(model);
  state.root_velocity.setZero();
  state.joints[0].omega.setZero();
  state.joints[0].alpha.setZero();
  state.root_acceleration.setZero();
  inverse_dynamics(model, data, state);
  state.root_position += com_position - data.com;

  const Vec6<double> h_joints = spatial_momentum_at_root(model, data);  // root at rest
  const Mat6<double> ic = composite_inertia_at_root(model, data);
  const Eigen::Matrix3d r0 = data.world_rotation[0];
  const Eigen::Vector3d linear = model.total_mass() * com_velocity;
  // Angular momentum about the root origin: L_O = L_G + (G − O) × P.
  const Eigen::Vector3d angular_at_root =
      angular_momentum + (com_position - state.root_position).cross(linear);
  // Head and tail assigned separately: GCC 12 misreads the comma initializer's 3-vector
  // temporaries as 4-wide AVX loads (a false -Warray-bounds).
  Vec6<double> wanted;
  wanted.head<3>() = r0.transpose() * angular_at_root;
  wanted.tail<3>() = r0.transpose() * linear;
  const Vec6<double> v0 = ic.ldlt().solve(wanted - h_joints);
  state.joints[0].omega = v0.head<3>();
  state.root_velocity = r0 * v0.tail<3>();
}

namespace {

struct RootState {
  Eigen::Quaterniond q;
  Eigen::Vector3d omega, position, velocity;
};

struct RootRate {
  Eigen::Vector4d dq;  // coefficients (x, y, z, w) as Eigen stores them
  Eigen::Vector3d domega, dposition, dvelocity;
};

/// The joints' state in `scratch` is for this time (NaN: none yet). An RK4 step asks for the
/// joints twice at its midpoint and its end is the next step's start: each is evaluated once.
struct JointsAt {
  double time = std::numeric_limits<double>::quiet_NaN();
};

RootRate rate(const BodyModel& model, const JointMotion& joint_motion, double t, const RootState& y,
              BodyState<double>& scratch, JointsAt& joints_at) {
  // The root solve below changes only the root's entries of `scratch`.
  if (!(t == joints_at.time)) {
    joint_motion(t, scratch);
    joints_at.time = t;
  }
  scratch.joints[0].q = y.q.normalized();
  scratch.joints[0].omega = y.omega;
  scratch.root_position = y.position;
  scratch.root_velocity = y.velocity;
  solve_free_root_acceleration(model, scratch);
  // q̇ = ½ q ⊗ (0, ω) with ω in the body frame.
  const Eigen::Quaterniond w(0.0, y.omega.x(), y.omega.y(), y.omega.z());
  RootRate r;
  r.dq = 0.5 * (y.q * w).coeffs();
  r.domega = scratch.joints[0].alpha;
  r.dposition = y.velocity;
  r.dvelocity = scratch.root_acceleration;
  return r;
}

RootState advance(const RootState& y, const RootRate& r, double h) {
  RootState out;
  out.q.coeffs() = y.q.coeffs() + h * r.dq;
  out.omega = y.omega + h * r.domega;
  out.position = y.position + h * r.dposition;
  out.velocity = y.velocity + h * r.dvelocity;
  return out;
}

RootState rk4_step(const BodyModel& model, const JointMotion& joint_motion, double t,
                   const RootState& y, double h, BodyState<double>& scratch, JointsAt& joints_at) {
  const RootRate k1 = rate(model, joint_motion, t, y, scratch, joints_at);
  const RootRate k2 =
      rate(model, joint_motion, t + h / 2, advance(y, k1, h / 2), scratch, joints_at);
  const RootRate k3 =
      rate(model, joint_motion, t + h / 2, advance(y, k2, h / 2), scratch, joints_at);
  const RootRate k4 = rate(model, joint_motion, t + h, advance(y, k3, h), scratch, joints_at);
  RootState out;
  out.q.coeffs() = y.q.coeffs() + h / 6 * (k1.dq + 2 * k2.dq + 2 * k3.dq + k4.dq);
  out.q.normalize();
  out.omega = y.omega + h / 6 * (k1.domega + 2 * k2.domega + 2 * k3.domega + k4.domega);
  out.position =
      y.position + h / 6 * (k1.dposition + 2 * k2.dposition + 2 * k3.dposition + k4.dposition);
  out.velocity =
      y.velocity + h / 6 * (k1.dvelocity + 2 * k2.dvelocity + 2 * k3.dvelocity + k4.dvelocity);
  return out;
}

}  // namespace

std::vector<BodyState<double>> simulate_free_flight(const BodyModel& model,
                                                    const JointMotion& joint_motion,
                                                    const FreeFlightInitialState& initial,
                                                    const std::vector<double>& times,
                                                    const FreeFlightOptions& options) {
  if (times.empty()) return {};
  if (!(options.max_step > 0)) throw std::invalid_argument("free flight: max_step must be > 0");
  for (std::size_t i = 1; i < times.size(); ++i)
    if (times[i] < times[i - 1])
      throw std::invalid_argument("free flight: times must not decrease");

  BodyState<double> state(model.size());
  joint_motion(times.front(), state);
  state.joints[0].q = initial.root_orientation.normalized();
  state.root_position.setZero();
  set_root_from_momentum(model, initial.com_position, initial.com_velocity,
                         initial.angular_momentum, state);

  RootState y{state.joints[0].q, state.joints[0].omega, state.root_position, state.root_velocity};
  BodyState<double> scratch(model.size());
  JointsAt joints_at;
  std::vector<BodyState<double>> out;
  out.reserve(times.size());
  // RK4 steps end exactly at the breakpoints: the joints' acceleration kinks there (a spline's
  // jerk jumps at its knots), and a step across a kink loses RK4's order.
  std::vector<double> breakpoints = options.breakpoints;
  std::sort(breakpoints.begin(), breakpoints.end());
  auto next_breakpoint = breakpoints.begin();
  double t = times.front();
  for (double target : times) {
    while (t < target) {
      while (next_breakpoint != breakpoints.end() && *next_breakpoint <= t)
        ++next_breakpoint;
      const double end = next_breakpoint != breakpoints.end() && *next_breakpoint < target
                             ? *next_breakpoint
                             : target;
      const double gap = end - t;
      const double step_count = std::ceil(gap / options.max_step - 1e-9);
      if (!(step_count <= kMaxFreeFlightSteps))
        throw std::invalid_argument(
            "free flight: more than 1e8 integration steps between two "
            "output times");
      const int steps = std::max(1, static_cast<int>(step_count));
      for (int k = 0; k < steps; ++k) {
        const double h = gap / steps;
        y = rk4_step(model, joint_motion, t, y, h, scratch, joints_at);
        t += h;
      }
      t = end;
    }
    t = target;
    BodyState<double> sample(model.size());
    joint_motion(t, sample);
    sample.joints[0].q = y.q;
    sample.joints[0].omega = y.omega;
    sample.root_position = y.position;
    sample.root_velocity = y.velocity;
    solve_free_root_acceleration(model, sample);
    out.push_back(std::move(sample));
  }
  return out;
}

}  // namespace saltus
