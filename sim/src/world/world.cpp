/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The world's physics on Box2D (world.h).
 *
 * Units: Box2D is tuned for bodies of 0.1 to 10 units, so one unit is a
 * centimetre here (a Kilobot 1.65 units across in radius, an arena 50 to
 * 200), masses in kilograms, time in seconds. The floor is seen from
 * above: no gravity in the plane; ground friction is a force that the
 * robots' legs and the objects' friction joints apply. A robot's legs are a
 * friction joint to a massless carrier that moves as the motors would walk
 * the robot: the joint pulls the robot along with at most the force its
 * legs can put on the floor (its weight times the leg friction), in the
 * same solver as the contacts (touching nothing, it is moved as the joint
 * alone would move it: walk). In free space it walks at the motors'
 * speed; a wall stops it, a light object is pushed at nearly its speed, a
 * heavy one may not budge. */
#include "world/world.h"

#include <box2d/box2d.h>

#include <array>
#include <cmath>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace {

constexpr double MM_PER_UNIT = 10.0;
constexpr double GRAVITY = 981.0;        /* cm / s^2 */
constexpr double KILOBOT_MASS_KG = 0.016; /* 16 g */
constexpr double LEG_FRICTION = 0.5;
/* The e-puck (docs/world.md): 150 g on two rubber-tyred wheels 41 mm
 * across, 53 mm apart, 1000 steps a turn. */
constexpr double EPUCK_MASS_KG = 0.150;
constexpr double EPUCK_WHEEL_FRICTION = 0.8;
constexpr double EPUCK_MM_PER_STEP = 3.14159265358979323846 * 41.0 / 1000.0;
constexpr double EPUCK_AXLE_MM = 53.0;
constexpr double CONTACT_FRICTION = 0.3; /* body against body */
constexpr int VELOCITY_ITERATIONS = 8, POSITION_ITERATIONS = 3;
constexpr double EDGE_PIECE_MM = 200.0; /* walls and obstacles' sides: add_outline */
constexpr double PI = 3.14159265358979323846;

b2Vec2 to_units(world_point p) { return b2Vec2(float(p.x / MM_PER_UNIT), float(p.y / MM_PER_UNIT)); }

struct Robot {
    b2Body *body = nullptr;
    b2Body *carrier = nullptr; /* kinematic, no shape: where the legs would take it */
    b2Joint *legs = nullptr;   /* to the carrier, while something is near (walk) */
    float grip_force = 0, grip_torque = 0; /* the most the legs put on the floor */
    kilobot_motors_model motors{};
    kilobot_motor motor[2]{};
    int16_t wheel_steps[2]{}; /* an e-puck's: steps/s, left and right */
    uint64_t rng = 0;
    /* What its legs walk it at in a step, drawn by world_step_prepare:
     * one for each step under way and one for the next (world.h). */
    kilobot_twist twist[WORLD_TWIST_SLOTS]{};
};

/* What a body is, in its user data: walls and obstacles carry 0. */
enum { TAG_ROBOT = 1, TAG_OBJECT = 2 };
uintptr_t tag(int kind, int index) { return (uintptr_t(kind) << 24) | uintptr_t(index); }

}  // namespace

struct world {
    const world_spec *spec = nullptr;
    b2World physics{b2Vec2(0.0f, 0.0f)};
    /* What objects' friction joints hold on to: a static body with no
     * shape, not the walls' (build_walls): a joint turns off collisions
     * between the bodies it joins (Box2D's collideConnected), so objects
     * joined to the walls' body passed through every wall and obstacle
     * (issue 30). */
    b2Body *floor = nullptr;
    /* The same walls and obstacles alone, for IR's rays: they are cast
     * while the physics steps on another thread (world_stepper.c), and a
     * static shape answers a ray the same in either world. */
    b2World walls{b2Vec2(0.0f, 0.0f)};
    std::vector<Robot> robots;
    std::vector<b2Body *> objects;
};

namespace {

/* An edge by its two ends, the lower first: the same either way round. */
using EdgeKey = std::array<double, 4>;
EdgeKey edge_key(world_point a, world_point b) {
    if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
    return {a.x, a.y, b.x, b.y};
}

/* A fixed outline: two-sided edges, so nothing passes from either side.
 * An edge already there (an obstacle given twice, two sharing a side) is
 * not added again: Box2D's broad phase pairs every two overlapping
 * fixtures of the walls' body when the world starts, before it drops the
 * pairs of one body, so N copies of one obstacle cost N^2 pairs (10000
 * copies: 2.7 GB, then a crash in b2BroadPhase; issue 30). */
void add_outline(b2Body *ground, const world_point *v, int n, std::set<EdgeKey> &added) {
    for (int i = 0; i < n; i++) {
        world_point a = v[i], b = v[(i + 1) % n];
        if (!added.insert(edge_key(a, b)).second) continue;
        /* In pieces of at most EDGE_PIECE_MM: an arena's wall as one edge
         * has a box as large as the arena in Box2D's broad-phase tree,
         * which every query for a moving robot then descends into
         * (docs/world.md, "Physics"). Collinear pieces of a two-sided
         * edge hold a disc as the whole edge does. */
        int pieces = int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / EDGE_PIECE_MM));
        if (pieces < 1) pieces = 1;
        for (int k = 0; k < pieces; k++) {
            double from = double(k) / pieces, to = double(k + 1) / pieces;
            b2EdgeShape edge;
            edge.SetTwoSided(to_units({a.x + (b.x - a.x) * from, a.y + (b.y - a.y) * from}),
                             to_units({a.x + (b.x - a.x) * to, a.y + (b.y - a.y) * to}));
            b2FixtureDef f;
            f.shape = &edge;
            f.friction = float(CONTACT_FRICTION);
            ground->CreateFixture(&f);
        }
    }
}

// The arena's walls and the obstacles, as one static body of edges.
void build_walls(b2World &in, const world_spec &s) {
    b2BodyDef def;
    b2Body *ground = in.CreateBody(&def);
    world_point arena[4] = {{0, 0}, {s.width_mm, 0}, {s.width_mm, s.height_mm}, {0, s.height_mm}};
    std::set<EdgeKey> added;
    add_outline(ground, arena, 4, added);
    for (int i = 0; i < s.n_obstacles; i++) add_outline(ground, s.obstacles[i].v, s.obstacles[i].n, added);
}

b2Body *add_disc(world &w, world_point at, double angle_deg, double radius_mm, double mass_kg) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = to_units(at);
    def.angle = float(angle_deg * PI / 180.0);
    def.bullet = false;
    b2Body *body = w.physics.CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = float(radius_mm / MM_PER_UNIT);
    b2FixtureDef f;
    f.shape = &circle;
    f.density = float(mass_kg / (PI * circle.m_radius * circle.m_radius));
    f.friction = float(CONTACT_FRICTION);
    f.restitution = 0.0f;
    body->CreateFixture(&f);
    return body;
}

/* An object slides on the floor against its friction: a friction joint to
 * the ground brakes it with at most friction x weight. */
void add_object(world &w, const world_object &o) {
    double mass = o.mass_g / 1000.0;
    b2Body *body = add_disc(w, o.at, 0.0, o.radius_mm, mass);
    body->GetUserData().pointer = tag(TAG_OBJECT, int(w.objects.size()));
    b2FrictionJointDef joint;
    joint.Initialize(body, w.floor, body->GetPosition());
    joint.maxForce = float(o.friction * mass * GRAVITY);
    joint.maxTorque = float(o.friction * mass * GRAVITY * o.radius_mm / MM_PER_UNIT / 2.0);
    w.physics.CreateJoint(&joint);
    w.objects.push_back(body);
}

/* The legs (a Kilobot's) or wheels (an e-puck's): a friction joint
 * between the robot and its carrier, at most the grip they have, anchored
 * at both centres. It is in the solver only while the robot has something
 * near (walk); the carrier too, which is otherwise left out (disabled). */
void attach_legs(world &w, Robot &r) {
    b2FrictionJointDef legs;
    legs.bodyA = r.body;
    legs.bodyB = r.carrier;
    legs.maxForce = r.grip_force;
    legs.maxTorque = r.grip_torque;
    r.carrier->SetEnabled(true);
    r.legs = w.physics.CreateJoint(&legs);
}

void detach_legs(world &w, Robot &r) {
    w.physics.DestroyJoint(r.legs);
    r.legs = nullptr;
    r.carrier->SetEnabled(false);
}

void add_legs(world &w, Robot &r, double friction, double mass_kg, double radius_mm) {
    b2BodyDef def;
    def.type = b2_kinematicBody;
    def.enabled = false;
    r.carrier = w.physics.CreateBody(&def);
    r.grip_force = float(friction * mass_kg * GRAVITY);
    r.grip_torque = float(friction * mass_kg * GRAVITY * radius_mm / MM_PER_UNIT);
}

/* A robot with nothing near: what its legs' joint alone does in the
 * solver, without the solver. The joint's impulse takes the robot's
 * velocity to the carrier's, clamped at the grip times the step (Box2D's
 * b2FrictionJoint: linear by length, angular by size; one iteration
 * reaches it, anchored at the centres), and Box2D then only moves it. */
void walk_free(Robot &r, b2Vec2 v, float turn) {
    b2Body *body = r.body;
    const float dt = float(WORLD_STEP_S);
    b2Vec2 dv = v - body->GetLinearVelocity();
    const float reach = r.grip_force * dt / body->GetMass();
    if (dv.LengthSquared() > reach * reach) {
        dv.Normalize();
        dv *= reach;
    }
    const float turn_reach = r.grip_torque * dt / body->GetInertia();
    const float dw = b2Clamp(turn - body->GetAngularVelocity(), -turn_reach, turn_reach);
    body->SetLinearVelocity(body->GetLinearVelocity() + dv);
    body->SetAngularVelocity(body->GetAngularVelocity() + dw);
}

/* Whether Box2D's next step finds the robot touching a body: its
 * contacts (the bodies within Box2D's margin of it) evaluated where the
 * bodies stand, as the step's collision pass evaluates them. */
bool touches_a_body(b2Body *body) {
    for (b2ContactEdge *edge = body->GetContactList(); edge != nullptr; edge = edge->next) {
        b2Contact *contact = edge->contact;
        b2Manifold manifold;
        contact->Evaluate(&manifold, contact->GetFixtureA()->GetBody()->GetTransform(),
                          contact->GetFixtureB()->GetBody()->GetTransform());
        if (manifold.pointCount > 0) return true;
    }
    return false;
}

/* Move the carrier as the motors would move the robot. Only its velocity
 * counts: the joint holds both bodies at their centres (attach_legs), so
 * the carrier's place and angle never enter the solver, and it is not put
 * on the robot each step (a SetTransform, a sincosf, per robot and step).
 * A robot whose motors are off is left to the solver: once it has been at
 * rest for Box2D's half second it sleeps and costs nothing per step until
 * its motors start or something pushes it - most of a settled swarm.
 * A robot that touches nothing in this step walks without the joint
 * (walk_free): the same motion, without the joint's share of the solver
 * (a quarter of the physics' work at a thousand packed robots). */
void walk(world &w, Robot &r, const kilobot_twist &twist) {
    const bool still = twist.forward_mm_s == 0 && twist.left_mm_s == 0 && twist.turn_rad_s == 0;
    if (still && !r.body->IsAwake()) return;
    /* The heading's sine and cosine as Box2D keeps them for the body
     * (floats), not computed again from its angle in doubles: a third of
     * walk's work. */
    const b2Rot &heading = r.body->GetTransform().q;
    double c = heading.c, s = heading.s;
    b2Vec2 v(float((twist.forward_mm_s * c - twist.left_mm_s * s) / MM_PER_UNIT),
             float((twist.forward_mm_s * s + twist.left_mm_s * c) / MM_PER_UNIT));
    if (!touches_a_body(r.body)) {
        if (r.legs != nullptr) detach_legs(w, r);
        walk_free(r, v, float(twist.turn_rad_s));
        return;
    }
    if (r.legs == nullptr) attach_legs(w, r);
    r.carrier->SetLinearVelocity(v);
    r.carrier->SetAngularVelocity(float(twist.turn_rad_s));
    if (!still) r.body->SetAwake(true);
}

/* A differential drive: each wheel rolls its steps' worth times its
 * factor; the body turns by their difference over the axle. */
kilobot_twist epuck_twist(const int16_t steps[2], const double factor[2]) {
    double left = steps[0] * EPUCK_MM_PER_STEP * factor[0], right = steps[1] * EPUCK_MM_PER_STEP * factor[1];
    return kilobot_twist{(left + right) / 2.0, 0.0, (right - left) / EPUCK_AXLE_MM};
}

/* The nearest body on a ray but one (the robot looking). */
class NearestOnRay : public b2RayCastCallback {
  public:
    explicit NearestOnRay(const b2Body *self) : self_(self) {}
    b2Body *body = nullptr;
    float fraction = 1.0f;
    float ReportFixture(b2Fixture *fixture, const b2Vec2 &, const b2Vec2 &, float f) override {
        if (fixture->GetBody() == self_) return -1.0f; /* ignore it */
        body = fixture->GetBody();
        fraction = f;
        return f; /* only nearer ones from now on */
    }

  private:
    const b2Body *self_;
};

/* Stops at the first shape on the ray in the world of walls alone: robots
 * and objects are low enough for IR to pass over or around, walls and
 * obstacles are not. */
class WallOnRay : public b2RayCastCallback {
  public:
    bool hit = false;
    float ReportFixture(b2Fixture *, const b2Vec2 &, const b2Vec2 &, float) override {
        hit = true;
        return 0.0f; /* one is enough */
    }
};

}  // namespace

extern "C" {

world *world_create(const world_spec *spec) {
    auto w = std::make_unique<world>();
    w->spec = spec;
    build_walls(w->physics, *spec);
    b2BodyDef floor_def;
    w->floor = w->physics.CreateBody(&floor_def);
    build_walls(w->walls, *spec);
    for (int k = 0; k < spec->n_objects; k++) add_object(*w, spec->objects[k]);
    uint64_t seed = spec->seed;
    w->robots.resize(size_t(spec->n_robots));
    for (int i = 0; i < spec->n_robots; i++) {
        Robot &r = w->robots[size_t(i)];
        /* Each robot its own stream, from the seed and its index alone. */
        r.rng = world_random_stream(seed, uint64_t(i));
        kilobot_motors_draw(&r.motors, &r.rng);
        const world_robot &spec_robot = spec->robots[i];
        const bool epuck = spec->robot_kind == WORLD_ROBOT_EPUCK;
        double mass = epuck ? EPUCK_MASS_KG : KILOBOT_MASS_KG;
        double radius = world_robot_radius(spec);
        r.body = add_disc(*w, spec_robot.at, spec_robot.heading_deg, radius, mass);
        r.body->GetUserData().pointer = tag(TAG_ROBOT, i);
        add_legs(*w, r, epuck ? EPUCK_WHEEL_FRICTION : LEG_FRICTION, mass, radius);
    }
    /* A step of no time only finds the new bodies' contacts (Box2D finds
     * them at its next step): a robot placed against another body then
     * walks with its legs' joint from the first step (walk). */
    w->physics.Step(0.0f, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    return w.release();
}

void world_destroy(world *w) { delete w; }

const world_spec *world_spec_of(const world *w) { return w->spec; }

const kilobot_motors_model *world_robot_motors(const world *w, int i) {
    return &w->robots[size_t(i)].motors;
}

void world_motor_duty(world *w, int i, int side, uint8_t duty, double t) {
    Robot &r = w->robots[size_t(i)];
    kilobot_motor_set(&r.motor[side], &r.motors, side, duty, t);
}

void world_epuck_wheels(world *w, int i, int16_t left, int16_t right) {
    Robot &r = w->robots[size_t(i)];
    r.wheel_steps[0] = left;
    r.wheel_steps[1] = right;
}

/* The motors' part: the same draws from each robot's own stream, in the
 * same order, whichever share and thread it falls to. */
void world_step_prepare(world *w, double t, unsigned slot, int share, int shares) {
    const bool epuck = w->spec->robot_kind == WORLD_ROBOT_EPUCK;
    const double wheel_noise = world_wheel_noise(w->spec);
    for (size_t i = size_t(share); i < w->robots.size(); i += size_t(shares)) {
        Robot &r = w->robots[i];
        if (epuck) {
            double factor[2] = {1.0, 1.0};
            if (wheel_noise > 0) /* drawn from the robot's own stream */
                for (double &f : factor) f += wheel_noise * (2.0 * world_random_uniform(&r.rng) - 1.0);
            r.twist[slot] = epuck_twist(r.wheel_steps, factor);
            continue;
        }
        for (kilobot_motor &motor : r.motor) kilobot_motor_advance(&motor, t);
        r.twist[slot] = kilobot_motion(r.motor, &r.motors, WORLD_STEP_S, &r.rng);
    }
}

void world_step_bodies(world *w, unsigned slot) {
    for (Robot &r : w->robots) walk(*w, r, r.twist[slot]);
    w->physics.Step(float(WORLD_STEP_S), VELOCITY_ITERATIONS, POSITION_ITERATIONS);
}

void world_step(world *w, double t) {
    world_step_prepare(w, t, 0, 0, 1);
    world_step_bodies(w, 0);
}

void world_robot_pose(const world *w, int i, double *x_mm, double *y_mm, double *heading_deg) {
    const b2Body *body = w->robots[size_t(i)].body;
    b2Vec2 p = body->GetPosition();
    *x_mm = p.x * MM_PER_UNIT;
    *y_mm = p.y * MM_PER_UNIT;
    double deg = std::fmod(body->GetAngle() * 180.0 / PI, 360.0);
    *heading_deg = deg < 0 ? deg + 360.0 : deg;
}

int world_blocks_ir(const world *w, double ax_mm, double ay_mm, double bx_mm, double by_mm) {
    b2Vec2 a = to_units({ax_mm, ay_mm}), b = to_units({bx_mm, by_mm});
    if ((b - a).LengthSquared() == 0.0f) return 0;
    WallOnRay ray;
    w->walls.RayCast(&ray, a, b);
    return ray.hit;
}

world_hit world_ray(const world *w, int self, double x_mm, double y_mm, double heading_deg,
                    double max_mm) {
    double a = heading_deg * PI / 180.0;
    b2Vec2 from = to_units({x_mm, y_mm});
    b2Vec2 to = to_units({x_mm + max_mm * std::cos(a), y_mm + max_mm * std::sin(a)});
    NearestOnRay ray(self >= 0 ? w->robots[size_t(self)].body : nullptr);
    w->physics.RayCast(&ray, from, to);
    world_hit hit{WORLD_HIT_NONE, -1, max_mm};
    if (ray.body == nullptr) return hit;
    hit.distance_mm = ray.fraction * max_mm;
    uintptr_t t = ray.body->GetUserData().pointer;
    int kind = int(t >> 24);
    hit.kind = kind == TAG_ROBOT ? WORLD_HIT_ROBOT : kind == TAG_OBJECT ? WORLD_HIT_OBJECT : WORLD_HIT_WALL;
    hit.index = kind ? int(t & 0xFFFFFF) : -1;
    return hit;
}

void world_object_position(const world *w, int k, double *x_mm, double *y_mm) {
    b2Vec2 p = w->objects[size_t(k)]->GetPosition();
    *x_mm = p.x * MM_PER_UNIT;
    *y_mm = p.y * MM_PER_UNIT;
}

}  // extern "C"
