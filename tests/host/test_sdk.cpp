// The C++ SDK on the host port: typed events, handlers as template
// arguments and as lambdas, conditions, threads, the RAII critical section.
#include "kernel_fixture.hpp"

#include "openswarm/openswarm.hpp"

using Sdk = KernelTest;
using openswarm::Event;

struct Reading {
    int16_t x, y;
};
static constexpr Event<Reading> reading{EV_A};
static constexpr Event<int16_t> number{EV_B};

static std::atomic<int> sum{0};
static void add(const int16_t &v) { sum += v; }
static bool over_ten(const int16_t &v) { return v > 10; }

TEST_F(Sdk, TypedEventsReachFunctionAndLambdaHandlers) {
    sum = 0;
    static std::atomic<int> last_x{0};
    last_x = 0;
    boot([] {
        EXPECT_STATUS(SYS_OK, reading.enroll());
        EXPECT_STATUS(SYS_OK, number.enroll());
        EXPECT_STATUS(SYS_OK, number.subscribe<&add>());
        EXPECT_STATUS(SYS_E_EXISTS, number.subscribe<&add>()) << "once per (event, thread)";
        EXPECT_STATUS(SYS_OK, reading.subscribe([](const Reading &r) { last_x = r.x; }));
    });
    irq([] {
        number.send(5);
        number.send(7);
        reading.send(Reading{3, 4});
    });
    settle();
    EXPECT_EQ(12, sum.load());
    EXPECT_EQ(3, last_x.load());
    Reading kept{};
    irq([&] { EXPECT_STATUS(SYS_OK, reading.last(kept)); });
    EXPECT_EQ(4, kept.y);
}

TEST_F(Sdk, ThreadsWaitWithTypedDataAndConditions) {
    static std::atomic<int> got{0}, big{0};
    got = big = 0;
    boot([] {
        number.enroll();
        EXPECT_STATUS(SYS_OK, openswarm::Thread::start([] {
            int16_t v = 0;
            number.wait(v);
            got = v;
            number.wait_until<&over_ten>(v);
            big = v;
        }));
    });
    settle();
    irq([] { number.send(2); });
    settle();
    irq([] {
        number.send(9);
        number.send(11);
    });
    settle();
    EXPECT_EQ(2, got.load());
    EXPECT_EQ(11, big.load());
}

TEST_F(Sdk, CriticalSectionGuardEndsWithItsScope) {
    static std::atomic<int> handled{0};
    handled = 0;
    boot([] {
        number.enroll();
        number.subscribe([](const int16_t &) { handled++; });
        openswarm::Thread::start([] {
            {
                openswarm::CriticalSection guard;
                number.send(1);
                EXPECT_EQ(0, handled.load()) << "postponed inside the section";
            }
            EXPECT_EQ(1, handled.load()) << "run when the guard went";
        });
    });
    settle();
    EXPECT_EQ(1, handled.load());
}

// Handlers with context: a lambda with captures (a reference and a value),
// a member function with its object; each unsubscribes; a second
// subscription of the same lambda or method is refused while one lasts.
struct Accumulator {
    int total = 0;
    void on_number(const int16_t &v) { total += v; }
};

TEST_F(Sdk, CapturingLambdasAndMemberFunctionsGetTheirContext) {
    static int captured_sum;
    static Accumulator acc, other;
    static sys_status again, method_again, method_off, lambda_off;
    captured_sum = 0;
    acc.total = other.total = 0;
    boot([this] {
        number.enroll();
        int &into = captured_sum;
        const int16_t scale = 10;
        auto scaled = [&into, scale](const int16_t &v) { into += v * scale; };
        EXPECT_STATUS(SYS_OK, number.subscribe(scaled));
        again = number.subscribe(scaled);
        EXPECT_STATUS(SYS_OK, (number.subscribe<Accumulator, &Accumulator::on_number>(acc)));
        method_again = number.subscribe<Accumulator, &Accumulator::on_number>(other);
        spawn([scaled] {
            number.send(2);
            number.send(3);
            lambda_off = number.unsubscribe(scaled);
            method_off = number.unsubscribe<Accumulator, &Accumulator::on_number>(acc);
            number.send(100); // nobody listens any more
        });
    });
    settle();
    EXPECT_STATUS(SYS_E_EXISTS, again);
    EXPECT_STATUS(SYS_E_EXISTS, method_again);
    EXPECT_STATUS(SYS_OK, lambda_off);
    EXPECT_STATUS(SYS_OK, method_off);
    EXPECT_EQ(50, captured_sum);
    EXPECT_EQ(5, acc.total);
    EXPECT_EQ(0, other.total);
}

// Handlers that end their own subscription by returning false: a function,
// a lambda without captures, and one with captures (which may then be
// subscribed again: its copy is free).
static int counted;
static bool count_to_two(const int16_t &) { return ++counted < 2; }

TEST_F(Sdk, HandlersReturningFalseUnsubscribeThemselves) {
    static int lambda_calls, captured_total;
    static sys_status again;
    counted = lambda_calls = captured_total = 0;
    again = SYS_E_INVALID;
    boot([this] {
        number.enroll();
        EXPECT_STATUS(SYS_OK, number.subscribe<&count_to_two>());
        EXPECT_STATUS(SYS_OK, number.subscribe([](const int16_t &) { return ++lambda_calls < 3; }));
        int &into = captured_total;
        auto until_big = [&into](const int16_t &v) {
            into += v;
            return v < 10;
        };
        EXPECT_STATUS(SYS_OK, number.subscribe(until_big));
        spawn([until_big] {
            for (int16_t v : {1, 10, 100, 1000}) number.send(v);
            again = number.subscribe(until_big);
            number.send(5);
        });
    });
    settle();
    EXPECT_EQ(2, counted) << "the function handler ended itself at its second call";
    EXPECT_EQ(3, lambda_calls) << "the lambda ended itself at its third call";
    EXPECT_STATUS(SYS_OK, again) << "a capturing lambda that ended itself can subscribe again";
    EXPECT_EQ(1 + 10 + 5, captured_total);
}

// Methods and events without data end their own subscriptions too: a
// method returning bool (its object then free for another subscription),
// and on an Event<void> a function, a lambda without captures, one with
// captures and a method.
struct Budget {
    int left = 0, spent = 0;
    bool spend(const int16_t &v) {
        spent += v;
        return --left > 0;
    }
    int rings = 0;
    bool ring() { return ++rings < 2; }
};
static constexpr Event<void> bell{EV_C};
static int bell_function_calls;
static bool ring_twice() { return ++bell_function_calls < 2; }

TEST_F(Sdk, MethodsAndDatalessHandlersEndThemselves) {
    static Budget budget, next;
    static int lambda_rings, captured_rings;
    static sys_status method_again, captured_again, off_after_end;
    budget = Budget{};
    next = Budget{};
    budget.left = 2;
    next.left = 5;
    bell_function_calls = lambda_rings = captured_rings = 0;
    boot([this] {
        number.enroll();
        bell.enroll();
        EXPECT_STATUS(SYS_OK, (number.subscribe<Budget, &Budget::spend>(budget)));
        EXPECT_STATUS(SYS_E_EXISTS, (number.subscribe<Budget, &Budget::spend>(next))) << "one object at a time";
        EXPECT_STATUS(SYS_OK, bell.subscribe<&ring_twice>());
        EXPECT_STATUS(SYS_OK, bell.subscribe([] { return ++lambda_rings < 3; }));
        int &into = captured_rings;
        auto three = [&into] { return ++into < 3; };
        EXPECT_STATUS(SYS_OK, bell.subscribe(three));
        EXPECT_STATUS(SYS_OK, (bell.subscribe<Budget, &Budget::ring>(budget)));
        spawn([three] {
            for (int16_t v : {1, 10, 100}) number.send(v);
            for (int i = 0; i < 5; i++) bell.send();
            method_again = number.subscribe<Budget, &Budget::spend>(next);
            number.send(7);
            captured_again = bell.subscribe(three);
            off_after_end = bell.unsubscribe<Budget, &Budget::ring>(budget);
        });
    });
    settle();
    EXPECT_EQ(11, budget.spent) << "the method ended itself at its second call";
    EXPECT_STATUS(SYS_OK, method_again) << "its binding is free again for another object";
    EXPECT_EQ(7, next.spent);
    EXPECT_EQ(2, bell_function_calls);
    EXPECT_EQ(3, lambda_rings);
    EXPECT_EQ(3, captured_rings);
    EXPECT_STATUS(SYS_OK, captured_again) << "a capturing lambda that ended itself can subscribe again";
    EXPECT_EQ(2, budget.rings);
    EXPECT_STATUS(SYS_E_NOT_FOUND, off_after_end) << "a method that ended itself is no longer subscribed";
}

TEST_F(Sdk, WaitUntilGivesUpAfterItsTimeout) {
    static sys_status timed_out, satisfied;
    static int16_t big;
    static uint32_t waited;
    timed_out = satisfied = SYS_E_INVALID;
    big = 0;
    boot([] {
        number.enroll();
        openswarm::Thread::start([] {
            int16_t v = 0;
            uint32_t from = openswarm::now_ms();
            timed_out = number.wait_until<&over_ten>(v, 50);
            waited = openswarm::now_ms() - from;
            satisfied = number.wait_until<&over_ten>(v, 1000);
            big = v;
        });
    });
    settle();
    irq([] { number.send(3); }); // not over ten: the wait goes on
    advance(60);
    irq([] { number.send(42); });
    settle();
    EXPECT_STATUS(SYS_E_TIMEOUT, timed_out);
    EXPECT_GE(waited, 50u);
    EXPECT_STATUS(SYS_OK, satisfied);
    EXPECT_EQ(42, big);
}
