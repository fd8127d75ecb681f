// Event registration, subscription, sending and dispatch.
#include "kernel_fixture.hpp"

#include <cstring>

using Events = KernelTest;

static bool log_handler(sys_pid pid, sys_event_id event, const sys_event_data *d) {
    std::string s = "h" + std::to_string(event - EV_A) + "(" + std::to_string(pid & 0x0F);
    if (d->size == sizeof(int16_t)) {
        int16_t v;
        std::memcpy(&v, d->value, sizeof v);
        s += "," + std::to_string(v);
    }
    note(s + ")");
    return true;
}
static bool second_handler(sys_pid, sys_event_id, const sys_event_data *) {
    note("second");
    return true;
}
static bool third_handler(sys_pid, sys_event_id, const sys_event_data *) {
    note("third");
    return true;
}

TEST_F(Events, RegisterUnregisterAndQuery) {
    sys_status first = SYS_E_INVALID, again = SYS_OK, out_of_range = SYS_OK, unreg = SYS_E_INVALID,
               unreg_again = SYS_OK, unreg_range = SYS_OK;
    bool during = false, after = true;
    boot([&] {
        first = Sys_Register_Event(EV_A);
        again = Sys_Register_Event(EV_A);
        out_of_range = Sys_Register_Event(OS_CFG_MAX_EVENTS);
        during = Sys_IsEventRegistered(EV_A);
        unreg = Sys_Unregister_Event(EV_A);
        unreg_again = Sys_Unregister_Event(EV_A);
        unreg_range = Sys_Unregister_Event(200);
        after = Sys_IsEventRegistered(EV_A);
    });
    settle();
    EXPECT_STATUS(SYS_OK, first);
    EXPECT_STATUS(SYS_E_EXISTS, again);
    EXPECT_STATUS(SYS_E_INVALID, out_of_range);
    EXPECT_TRUE(during);
    EXPECT_STATUS(SYS_OK, unreg);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, unreg_again);
    EXPECT_STATUS(SYS_E_INVALID, unreg_range);
    EXPECT_FALSE(after);
}

TEST_F(Events, HandlerSubscribedAtMostOncePerEventAndThread) {
    sys_status first = SYS_E_INVALID, dup = SYS_OK, other_thread = SYS_E_INVALID,
               other_event = SYS_E_INVALID;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        sys_pid t = spawn([] { Sys_Sleep(100000); });
        first = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        dup = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        other_thread = Sys_Subscribe_to_Event(EV_A, t, log_handler, nullptr);
        other_event = Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_STATUS(SYS_OK, first);
    EXPECT_STATUS(SYS_E_EXISTS, dup);
    EXPECT_STATUS(SYS_OK, other_thread);
    EXPECT_STATUS(SYS_OK, other_event);
    ASSERT_EQ(2u, trace().size()) << joined() << ": once per (event, thread)";
    EXPECT_EQ("h0(0)", trace()[0]);
}

TEST_F(Events, SubscribeChecksItsArguments) {
    sys_status unregistered = SYS_OK, no_handler = SYS_OK, bad_pid = SYS_OK, unknown = SYS_OK;
    boot([&] {
        unregistered = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        Sys_Register_Event(EV_A);
        no_handler = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, nullptr, nullptr);
        bad_pid = Sys_Subscribe_to_Event(EV_A, 0x07, log_handler, nullptr);
        unknown = Sys_Unsubscribe_from_Event(EV_A, SYS_PID_SYSTEM, log_handler);
    });
    settle();
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, unregistered);
    EXPECT_STATUS(SYS_E_INVALID, no_handler);
    EXPECT_STATUS(SYS_E_INVALID, bad_pid);
    EXPECT_STATUS(SYS_E_NOT_FOUND, unknown);
}

TEST_F(Events, UnsubscribedHandlerNoLongerRuns) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] { Sys_Send_IntEvent(EV_A, 1); });
    irq([] { EXPECT_STATUS(SYS_OK, Sys_Unsubscribe_from_Event(EV_A, SYS_PID_SYSTEM, log_handler)); });
    irq([] { Sys_Send_IntEvent(EV_A, 2); });
    settle();
    EXPECT_EQ("h0(0,1)", joined());
}

TEST_F(Events, HandlersRunInTheOrderEventsWereSent) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] {
        Sys_Send_IntEvent(EV_B, 1);
        Sys_Send_IntEvent(EV_A, 2);
        Sys_Send_IntEvent(EV_B, 3);
    });
    settle();
    EXPECT_EQ("h1(0,1) h0(0,2) h1(0,3)", joined());
}

TEST_F(Events, HandlersOfOneEventRunInSubscriptionOrder) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, third_handler, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, second_handler, nullptr);
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("third h0(0) second", joined());
}

// Unsubscribing only marks an entry; a subscription that needs its room
// gets it, and the handlers left keep their order.
static bool new_handler(sys_pid, sys_event_id, const sys_event_data *) {
    note("new");
    return true;
}
static bool quiet_handler(sys_pid, sys_event_id, const sys_event_data *) { return true; }

TEST_F(Events, UnsubscribedEntriesMakeRoomAndTheOrderStays) {
    sys_status fill = SYS_E_INVALID, full = SYS_OK, unsub = SYS_E_INVALID, null_handler = SYS_OK,
               reuse = SYS_E_INVALID, full_again = SYS_OK;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, third_handler, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, second_handler, nullptr);
        for (sys_event_id e = EV_B; e < EV_B + OS_CFG_MAX_SUBSCRIPTIONS - 3; e++) {
            Sys_Register_Event(e);
            fill = Sys_Subscribe_to_Event(e, SYS_PID_SYSTEM, log_handler, nullptr);
        }
        full = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, new_handler, nullptr);
        unsub = Sys_Unsubscribe_from_Event(EV_A, SYS_PID_SYSTEM, log_handler);
        null_handler = Sys_Unsubscribe_from_Event(EV_A, SYS_PID_SYSTEM, nullptr);
        reuse = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, new_handler, nullptr);
        full_again = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, quiet_handler, nullptr);
    });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_STATUS(SYS_OK, fill);
    EXPECT_STATUS(SYS_E_POOL_FULL, full);
    EXPECT_STATUS(SYS_OK, unsub);
    EXPECT_STATUS(SYS_E_NOT_FOUND, null_handler) << "a NULL handler names no subscription";
    EXPECT_STATUS(SYS_OK, reuse) << "the unsubscribed entry makes room";
    EXPECT_STATUS(SYS_E_POOL_FULL, full_again);
    EXPECT_EQ("third second new", joined());
    EXPECT_EQ(2u, stats().subscription_pool_full);
}

TEST_F(Events, SendCopiesTheData) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] {
        int16_t v = 41;
        Sys_Send_Event(EV_A, &v, sizeof v);
        v = 99; // the handler runs after the interrupt: it must see 41
        Sys_Send_Event(EV_A, &v, sizeof v);
    });
    settle();
    EXPECT_EQ("h0(0,41) h0(0,99)", joined());
}

TEST_F(Events, SendFromAThreadRunsHandlersBeforeItReturns) {
    sys_pid self = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        self = spawn([] {
            note("before");
            Sys_Send_IntEvent(EV_A, 7);
            note("after");
        });
    });
    settle();
    EXPECT_EQ("before h0(0,7) after", joined());
}

TEST_F(Events, SendFromAnInterruptRunsHandlersWhenItReturnsAndTheThreadKeepsItsSlice) {
    static std::atomic<int> handled{0};
    static std::atomic<sys_pid> handler_context{SYS_PID_NONE};
    handled = 0;
    std::atomic<long> a{0}, b{0};
    sys_pid pa = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   handler_context = Sys_Get_ProcessID();
                                   handled++;
                                   return true;
                               },
                               nullptr);
        pa = spawn([&] {
            for (;;) a++;
        });
        spawn([&] {
            for (;;) b++;
        });
    });
    advance(2);
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    // host_cpu_interrupt returns once the CPU is back in thread code: the
    // handler has already run, with no tick in between.
    EXPECT_EQ(1, handled.load());
    EXPECT_EQ(SYS_PID_SYSTEM, handler_context.load()) << "handlers run in the system thread";
    EXPECT_EQ(pa, running()) << "the interrupted thread resumes its slice";
    advance(OS_CFG_TIME_SLICE_MS - 3);
    EXPECT_EQ(pa, running());
    advance(1);
    EXPECT_NE(pa, running()) << "and its slice ends on time";
    power_off();
}

TEST_F(Events, HandlerGetsTheSubscribingThreadsPid) {
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        t = spawn([] { Sys_Sleep(100000); });
        Sys_Subscribe_to_Event(EV_A, t, log_handler, nullptr);
    });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("h0(" + std::to_string(t & 0x0F) + ")", joined());
}

TEST_F(Events, HandlerReturningFalseIsUnsubscribed) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   note("once");
                                   return false;
                               },
                               nullptr);
    });
    for (int i = 0; i < 3; i++) irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("once", joined());
}

TEST_F(Events, ConditionFiltersOccurrencesForAHandler) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, [](const sys_event_data *d) {
            int16_t v;
            std::memcpy(&v, d->value, sizeof v);
            return v % 2 == 0;
        });
    });
    irq([] {
        for (int16_t v = 1; v <= 5; v++) Sys_Send_IntEvent(EV_A, v);
    });
    settle();
    EXPECT_EQ("h0(0,2) h0(0,4)", joined());
}

TEST_F(Events, LastDataIsKeptUntilCleared) {
    sys_status before = SYS_OK, trunc = SYS_OK, after_clear = SYS_OK, unregistered = SYS_OK;
    int16_t got = 0;
    uint8_t size = 0, trunc_size = 0;
    uint8_t one = 0;
    boot([&] { Sys_Register_Event(EV_A); });
    irq([&] {
        before = Sys_Get_EventData(EV_A, &got, sizeof got, &size);
        Sys_Send_IntEvent(EV_A, 300);
        Sys_Send_IntEvent(EV_A, 1234);
    });
    settle();
    irq([&] {
        EXPECT_STATUS(SYS_OK, Sys_Get_EventData(EV_A, &got, sizeof got, &size));
        trunc = Sys_Get_EventData(EV_A, &one, 1, &trunc_size);
        Sys_Clear_EventData(EV_A);
        after_clear = Sys_Get_EventData(EV_A, &got, sizeof got, nullptr);
        unregistered = Sys_Get_EventData(EV_B, &got, sizeof got, nullptr);
    });
    EXPECT_STATUS(SYS_E_NOT_FOUND, before);
    EXPECT_EQ(1234, got);
    EXPECT_EQ(sizeof(int16_t), size);
    EXPECT_STATUS(SYS_E_TRUNCATED, trunc);
    EXPECT_EQ(2, trunc_size);
    EXPECT_EQ(1234 & 0xFF, one);
    EXPECT_STATUS(SYS_E_NOT_FOUND, after_clear);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, unregistered);
}

// An occurrence sent while the queue is empty is held in its event's kept
// data until dispatched; clearing the kept data meanwhile must not spoil it.
TEST_F(Events, ClearingKeptDataBeforeDispatchKeepsTheSentOccurrence) {
    int16_t got = 0;
    uint8_t size = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] {
        Sys_Send_IntEvent(EV_A, 7);
        EXPECT_STATUS(SYS_OK, Sys_Clear_EventData(EV_A));
    });
    settle();
    irq([&] { EXPECT_STATUS(SYS_OK, Sys_Get_EventData(EV_A, &got, sizeof got, &size)); });
    EXPECT_EQ("h0(0,7)", joined());
    EXPECT_EQ(7, got);
    EXPECT_EQ(sizeof got, size);
}

// A send of the event being handled must not overwrite the data its
// handlers are reading: it waits in the queue instead.
TEST_F(Events, HandlerSendingItsOwnEventKeepsReadingItsOwnData) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *d) {
                                   int16_t v;
                                   std::memcpy(&v, d->value, sizeof v);
                                   if (v == 1) Sys_Send_IntEvent(EV_A, 2);
                                   std::memcpy(&v, d->value, sizeof v);
                                   note("saw" + std::to_string(v));
                                   return true;
                               },
                               nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] { Sys_Send_IntEvent(EV_A, 1); });
    settle();
    EXPECT_EQ("saw1 h0(0,1) saw2 h0(0,2)", joined());
}

TEST_F(Events, BadSendsAreRefused) {
    sys_status too_big = SYS_OK, unregistered = SYS_OK, null_data = SYS_OK, range = SYS_OK;
    boot([&] { Sys_Register_Event_Sized(EV_A, 2); });
    irq([&] {
        uint8_t three[3] = {1, 2, 3};
        too_big = Sys_Send_Event(EV_A, three, 3);
        unregistered = Sys_Send_Event(EV_B, three, 1);
        null_data = Sys_Send_Event(EV_A, nullptr, 1);
        range = Sys_Send_Event(OS_CFG_MAX_EVENTS, three, 1);
    });
    EXPECT_STATUS(SYS_E_TOO_BIG, too_big);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, unregistered);
    EXPECT_STATUS(SYS_E_INVALID, null_data);
    EXPECT_STATUS(SYS_E_INVALID, range);
}

TEST_F(Events, EventSentByAHandlerRunsAfterTheCurrentOne) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   Sys_Send_IntEvent(EV_B, 5);
                                   note("a1");
                                   return true;
                               },
                               nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, second_handler, nullptr);
        Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM, log_handler, nullptr);
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("a1 second h1(0,5)", joined());
}

TEST_F(Events, HandlerSubscribedDuringDispatchWaitsForTheNextOccurrence) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   note("first");
                                   Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, second_handler,
                                                          nullptr);
                                   return true;
                               },
                               nullptr);
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("first first second", joined());
}

TEST_F(Events, OccurrencesOfAnEventUnregisteredBeforeDispatchAreCountedNotLost) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        spawn([] {
            Sys_Start_CriticalSection();
            Sys_Send_IntEvent(EV_A, 1);
            Sys_Send_IntEvent(EV_A, 2);
            EXPECT_STATUS(SYS_OK, Sys_Unregister_Event(EV_A));
            Sys_End_CriticalSection();
        });
    });
    settle();
    EXPECT_EQ("", joined());
    EXPECT_EQ(2u, stats().events_discarded);
}

TEST_F(Events, RegistrationFromAnInterruptIsRefused) {
    sys_status reg = SYS_OK, unreg = SYS_OK;
    boot([&] { Sys_Register_Event(EV_B); });
    irq([&] {
        reg = Sys_Register_Event(EV_A);
        unreg = Sys_Unregister_Event(EV_B);
    });
    EXPECT_STATUS(SYS_E_CONTEXT, reg);
    EXPECT_STATUS(SYS_E_CONTEXT, unreg);
}

TEST_F(Events, NoSubscriptionForAThreadBeingTornDown) {
    sys_status for_zombie = SYS_OK;
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            sys_pid victim = spawn([] { Sys_Sleep(100000); });
            Sys_Start_CriticalSection(); // keeps the victim a zombie, unreaped
            Sys_Kill_Process(victim);
            for_zombie = Sys_Subscribe_to_Event(EV_A, victim, log_handler, nullptr);
            Sys_End_CriticalSection();
        });
    });
    settle();
    EXPECT_STATUS(SYS_E_INVALID, for_zombie);
}

// Handlers with a context: two bindings of one function keep apart, each
// with its own pointer; a binding is subscribed once per (event, thread),
// a subscription of the same function without context is another one, and
// unsubscribing one binding leaves the other.
struct Counter {
    const char *name;
    int calls;
};
static bool count_with(void *context, sys_pid, const sys_event_data *) {
    auto *c = static_cast<Counter *>(context);
    c->calls++;
    note(c->name);
    return true;
}

TEST_F(Events, HandlersWithContextKeepTheirOwnPointer) {
    static Counter a{"a", 0}, b{"b", 0};
    static const sys_event_binding to_a{count_with, &a, nullptr}, to_b{count_with, &b, nullptr};
    sys_status sa = SYS_E_INVALID, sb = SYS_E_INVALID, again = SYS_OK, plain = SYS_E_INVALID, off = SYS_E_INVALID,
               off_again = SYS_OK;
    a.calls = b.calls = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        sa = Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_a);
        sb = Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_b);
        again = Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_a);
        plain = Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, log_handler, nullptr);
        spawn([&] {
            Sys_Send_Event(EV_A, nullptr, 0); // dispatched before Send returns
            off = Sys_Unsubscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_a);
            off_again = Sys_Unsubscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_a);
            Sys_Send_Event(EV_A, nullptr, 0);
        });
    });
    settle();
    EXPECT_STATUS(SYS_OK, sa);
    EXPECT_STATUS(SYS_OK, sb);
    EXPECT_STATUS(SYS_E_EXISTS, again);
    EXPECT_STATUS(SYS_OK, plain);
    EXPECT_STATUS(SYS_OK, off);
    EXPECT_STATUS(SYS_E_NOT_FOUND, off_again);
    EXPECT_EQ(1, a.calls);
    EXPECT_EQ(2, b.calls);
    EXPECT_EQ("a b h0(0) b h0(0)", joined());
}
