// Box2D's profiling clock is stopped in the simulator (sim/src/world/
// box2d_timer.cpp): a step of a spread-out swarm reads no clock, and the
// physics is unchanged (the same world stepped gives the same bodies).
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <chrono>
#include <thread>

namespace {

TEST(Box2dTimer, ReadsNoClock) {
    b2Timer timer;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_EQ(timer.GetMilliseconds(), 0.0f);
}

TEST(Box2dTimer, StepsProfileNothing) {
    b2World world(b2Vec2(0.0f, 0.0f));
    b2CircleShape disc;
    disc.m_radius = 1.65f;
    for (int i = 0; i < 200; i++) { /* an island each, as a dispersed swarm */
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(float(i % 20) * 5.0f, float(i / 20) * 5.0f);
        def.linearVelocity.Set(1.0f, 0.5f);
        world.CreateBody(&def)->CreateFixture(&disc, 1.0f);
    }
    for (int k = 0; k < 20; k++) world.Step(0.01f, 8, 3);
    EXPECT_EQ(world.GetProfile().step, 0.0f);
    EXPECT_EQ(world.GetProfile().solve, 0.0f);
}

}  // namespace
