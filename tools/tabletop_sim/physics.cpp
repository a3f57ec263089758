#include "tools/tabletop_sim/physics.h"

#include <cmath>
#include <deque>
#include <memory>

#include <btBulletDynamicsCommon.h>
#include <fmt/format.h>

#include "tools/tabletop_sim/bullet_units.h"

namespace ksmc::tools::tabletop_sim {

namespace {

constexpr double kGravity = 9.81;  // m/s^2

// One Bullet world holding the static table and the dynamic boxes. Members are declared in
// construction order so they are destroyed in reverse (bodies before the world).
class World {
 public:
  World(std::span<const SimBody> bodies, const TableSpec& table, const SettleParams& params)
      : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_) {
    world_.setGravity(btVector3(0, 0, static_cast<btScalar>(-kGravity * kBulletScale)));
    btContactSolverInfo& info = world_.getSolverInfo();
    info.m_numIterations = params.solver_iterations;
    info.m_solverMode &= ~SOLVER_RANDMIZE_ORDER;
    info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;

    const Eigen::Vector3d table_half(table.half_extent.x(), table.half_extent.y(), 0.5 * table.thickness);
    Pose table_pose;
    table_pose.t = Eigen::Vector3d(0, 0, -0.5 * table.thickness);
    add_body(table_half, table_pose, 0.0, table.friction);
    for (const SimBody& b : bodies) add_body(0.5 * b.box.size, b.box.pose, b.mass, b.friction);
  }

  World(const World&) = delete;
  World& operator=(const World&) = delete;

  ~World() {
    for (auto& b : bodies_) world_.removeRigidBody(b.get());
  }

  void step(double dt) { world_.stepSimulation(static_cast<btScalar>(dt), 0); }

  std::size_t box_count() const { return bodies_.size() - 1; }
  Pose pose(std::size_t i) const { return from_bullet(bodies_[i + 1]->getCenterOfMassTransform()); }
  double linear_speed(std::size_t i) const {
    return static_cast<double>(bodies_[i + 1]->getLinearVelocity().length()) / kBulletScale;
  }
  double angular_speed(std::size_t i) const {
    return static_cast<double>(bodies_[i + 1]->getAngularVelocity().length());
  }

 private:
  void add_body(const Eigen::Vector3d& half, const Pose& pose, double mass, double friction) {
    auto shape = std::make_unique<btBoxShape>(to_bullet_vector(half));
    shape->setMargin(static_cast<btScalar>(0.0005 * kBulletScale));  // 0.5 mm, inside the box
    btVector3 inertia(0, 0, 0);
    if (mass > 0.0) shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    btRigidBody::btRigidBodyConstructionInfo ci(static_cast<btScalar>(mass), nullptr, shape.get(), inertia);
    ci.m_startWorldTransform = to_bullet(pose);
    ci.m_friction = static_cast<btScalar>(friction);
    ci.m_restitution = 0.05f;
    ci.m_linearDamping = 0.05f;
    ci.m_angularDamping = 0.1f;
    auto body = std::make_unique<btRigidBody>(ci);
    // Sleeping would freeze slowly creeping stacks and fake a rest state; keep everyone awake.
    body->setActivationState(DISABLE_DEACTIVATION);
    // Friction anchors keep resting contacts from drifting sideways (Bullet's stacking fix).
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_HAS_FRICTION_ANCHOR);
    world_.addRigidBody(body.get());
    shapes_.push_back(std::move(shape));
    bodies_.push_back(std::move(body));
  }

  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;  // [0] is the table
};

bool off_table(const Pose& p, const TableSpec& table) {
  return p.t.z() < -0.01 || std::abs(p.t.x()) > table.half_extent.x() ||
         std::abs(p.t.y()) > table.half_extent.y();
}

}  // namespace

SettleResult settle(std::span<const SimBody> bodies, const TableSpec& table, const SettleParams& params) {
  World world(bodies, table, params);
  const double dt = params.time_step;
  const auto max_steps = static_cast<long>(std::ceil(params.max_time / dt));
  const auto rest_steps = static_cast<long>(std::ceil(params.rest_window / dt));
  const auto creep_steps = static_cast<long>(std::llround(params.creep_window / dt));
  const auto min_steps = static_cast<long>(std::ceil(params.min_time / dt));
  const long snapshot_every = std::max<long>(1, creep_steps / 20);

  // Snapshots of all poses every `snapshot_every` steps, covering the last creep window.
  std::deque<std::pair<long, std::vector<Pose>>> history;
  long quiet = 0;
  SettleResult result;
  for (long step = 1; step <= max_steps; ++step) {
    world.step(dt);
    bool calm = true;
    for (std::size_t i = 0; i < world.box_count(); ++i) {
      if (world.linear_speed(i) > params.linear_speed_tol || world.angular_speed(i) > params.angular_speed_tol) {
        calm = false;
        break;
      }
    }
    quiet = calm ? quiet + 1 : 0;

    if (step % snapshot_every != 0) continue;
    std::vector<Pose> now(world.box_count());
    for (std::size_t i = 0; i < now.size(); ++i) {
      now[i] = world.pose(i);
      if (off_table(now[i], table)) {
        result.status = SettleStatus::fell_off_table;
        result.time = static_cast<double>(step) * dt;
        result.detail = fmt::format("box {} left the table after {:.2f} s", i, result.time);
        result.poses = std::move(now);
        return result;
      }
    }
    history.emplace_back(step, now);
    // Keep the newest snapshot that is at least one creep window old, and everything after it.
    while (history.size() > 1 && history[1].first <= step - creep_steps) history.pop_front();

    if (step < min_steps || quiet < rest_steps || history.front().first > step - creep_steps) continue;
    const auto& before = history.front().second;
    bool creeping = false;
    for (std::size_t i = 0; i < now.size() && !creeping; ++i) {
      creeping = (now[i].t - before[i].t).norm() > params.creep_translation_tol ||
                 rotation_angle(now[i].q, before[i].q) > params.creep_rotation_tol;
    }
    if (creeping) continue;
    result.status = SettleStatus::settled;
    result.time = static_cast<double>(step) * dt;
    result.poses = std::move(now);
    return result;
  }
  result.status = SettleStatus::not_settled;
  result.time = static_cast<double>(max_steps) * dt;
  result.poses.resize(world.box_count());
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < result.poses.size(); ++i) {
    result.poses[i] = world.pose(i);
    if (world.linear_speed(i) > world.linear_speed(fastest)) fastest = i;
  }
  result.detail = fmt::format("not at rest after {:.1f} s (box {} at {:.1f} mm/s, {:.3f} rad/s, z {:.3f} m)", result.time,
                              fastest, 1000.0 * world.linear_speed(fastest), world.angular_speed(fastest),
                              result.poses[fastest].t.z());
  return result;
}

Drift resimulate(std::span<const SimBody> bodies, const TableSpec& table, const SettleParams& params,
                 double seconds) {
  World world(bodies, table, params);
  const auto steps = static_cast<long>(std::ceil(seconds / params.time_step));
  Drift drift;
  for (long s = 0; s < steps; ++s) {
    world.step(params.time_step);
    for (std::size_t i = 0; i < world.box_count(); ++i) {
      const Pose p = world.pose(i);
      const double dt = (p.t - bodies[i].box.pose.t).norm();
      const double dr = rotation_angle(p.q, bodies[i].box.pose.q);
      if (dt > drift.max_translation || dr > drift.max_rotation) drift.worst_body = static_cast<int>(i);
      drift.max_translation = std::max(drift.max_translation, dt);
      drift.max_rotation = std::max(drift.max_rotation, dr);
    }
  }
  return drift;
}

}  // namespace ksmc::tools::tabletop_sim
