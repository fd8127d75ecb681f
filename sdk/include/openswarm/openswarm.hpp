// The C++ API over the kernel's C calls: typed events, functions and
// lambdas as handlers and conditions, threads, and an RAII critical
// section. C++14 without the standard library (avr-g++ 5.4 has none), and
// no cost over the C calls: every wrapper is inline, and a handler given as
// a template argument is called directly.
//
//   constexpr openswarm::Event<int16_t> speed{SYS_EVENT_FIRST_FREE};
//   speed.enroll();
//   speed.subscribe<&on_speed>();                      // void on_speed(const int16_t &)
//   speed.subscribe([](const int16_t &v) { ... });     // a lambda without captures
//   speed.subscribe([](const int16_t &v) { return v < 100; }); // false: unsubscribes
//   speed.send(42);
//   int16_t v; speed.wait(v);
//   { openswarm::CriticalSection guard; ... }
#ifndef OPENSWARM_HPP
#define OPENSWARM_HPP

#include "openswarm/kernel.h"

namespace openswarm {

using Status = sys_status;

namespace detail {
// Does From convert to To (a lambda to a handler's function pointer)?
// Without the standard library's is_convertible.
template <typename From, typename To>
struct converts {
    static char test(To);
    static long test(...);
    static From &from();
    static const bool value = sizeof(test(from())) == 1;
};
template <typename A, typename B>
struct same {
    static const bool value = false;
};
template <typename A>
struct same<A, A> {
    static const bool value = true;
};
template <bool>
struct choice {};
// Is Lambda's call void(const T &) const or bool(const T &) const, exactly
// (a lambda taking another type would be called through a conversion,
// silently)?
template <typename Lambda, typename T>
struct handles {
    static const bool value = same<decltype(&Lambda::operator()), void (Lambda::*)(const T &) const>::value ||
                              same<decltype(&Lambda::operator()), bool (Lambda::*)(const T &) const>::value;
};
// What a handler's call returns: the kernel's "stay subscribed". A handler
// returning void stays; one returning bool says (false: unsubscribe).
template <typename F, typename... Args>
inline bool stays(choice<false>, const F &f, const Args &...args) noexcept {
    f(args...);
    return true;
}
template <typename F, typename... Args>
inline bool stays(choice<true>, const F &f, const Args &...args) noexcept {
    return f(args...);
}
template <typename X>
X make() noexcept;
template <typename F, typename... Args>
inline bool call_handler(const F &f, const Args &...args) noexcept {
    return stays(choice<same<decltype(make<const F &>()(make<const Args &>()...)), bool>::value>{}, f, args...);
}

// A handler with a context (an object, a lambda's captures): Call::run
// (context, data) calls it and says whether it stays subscribed. One
// binding per Call, so one context at a time (SYS_E_EXISTS for another).
// `owner` (not the binding, which the kernel may still read while it
// removes a subscription that ended itself) says which context is in use.
template <typename Call>
struct Bound {
    static sys_event_binding binding;
    static void *owner;
    static bool call(void *context, sys_pid, const sys_event_data *d) noexcept {
        bool stays = Call::run(context, d);
        if (!stays) owner = nullptr;
        return stays;
    }
    static sys_status subscribe(sys_event_id id, sys_pid pid, void *context) noexcept {
        if (owner != nullptr) return SYS_E_EXISTS;
        binding = {&call, context, nullptr};
        sys_status st = Sys_Subscribe_with_Context(id, pid, &binding);
        if (st == SYS_OK) owner = context;
        return st;
    }
    static sys_status unsubscribe(sys_event_id id, sys_pid pid, void *context) noexcept {
        if (owner == nullptr || owner != context) return SYS_E_NOT_FOUND;
        sys_status st = Sys_Unsubscribe_with_Context(id, pid, &binding);
        if (st == SYS_OK) owner = nullptr;
        return st;
    }
};
template <typename Call>
sys_event_binding Bound<Call>::binding = {nullptr, nullptr, nullptr};
template <typename Call>
void *Bound<Call>::owner = nullptr;

// Where a capturing lambda's captures are copied (as bytes) while it is
// subscribed: a static of its type.
template <typename Lambda>
struct Captures {
    alignas(Lambda) static unsigned char bytes[sizeof(Lambda)];
};
template <typename Lambda>
alignas(Lambda) unsigned char Captures<Lambda>::bytes[sizeof(Lambda)];

template <typename Call, typename Lambda>
inline sys_status subscribe_captures(sys_event_id id, sys_pid pid, const Lambda &lambda) noexcept {
    static_assert(__is_trivially_copyable(Lambda), "a lambda's captures must be values or references that copy as bytes");
    if (Bound<Call>::owner != nullptr) return SYS_E_EXISTS; // its copy is in use
    const unsigned char *from = reinterpret_cast<const unsigned char *>(&lambda);
    for (unsigned i = 0; i < sizeof(Lambda); i++) Captures<Lambda>::bytes[i] = from[i];
    return Bound<Call>::subscribe(id, pid, Captures<Lambda>::bytes);
}
}  // namespace detail

// The data of an event openswarm.json declares by "size" alone: N bytes.
template <uint8_t N>
struct Bytes {
    uint8_t bytes[N];
};

// An event whose data is one T (a plain struct or number).
template <typename T>
class Event {
    // Sizes travel as uint8_t: a bigger T would be cut short, silently.
    static_assert(sizeof(T) <= 253, "an event's data is at most 253 bytes (openswarm.json's limit)");

  public:
    using Handler = void (*)(const T &);
    using Condition = bool (*)(const T &);
    // A handler that may end its own subscription: false unsubscribes it.
    using EndingHandler = bool (*)(const T &);

    constexpr explicit Event(sys_event_id id) noexcept : id_(id) {}
    constexpr sys_event_id id() const noexcept { return id_; }

    // Register the event with room for one T.
    Status enroll() const noexcept { return Sys_Register_Event_Sized(id_, sizeof(T)); }

    Status send(const T &value) const noexcept { return Sys_Send_Event(id_, &value, sizeof(T)); }

    // Block the calling thread until the next occurrence; its data into out.
    Status wait(T &out) const noexcept { return Sys_Wait_for_Event(id_, &out, sizeof(T), nullptr); }
    Status wait(T &out, uint32_t timeout_ms) const noexcept {
        return Sys_Wait_for_Event_Timeout(id_, timeout_ms, &out, sizeof(T), nullptr);
    }

    // Block until an occurrence satisfies condition (a function given as a
    // template argument: called directly).
    template <Condition condition>
    Status wait_until(T &out) const noexcept {
        return Sys_Wait_for_Condition(id_, &check<condition>, &out, sizeof(T), nullptr);
    }
    // The same, giving up after timeout_ms: SYS_E_TIMEOUT.
    template <Condition condition>
    Status wait_until(T &out, uint32_t timeout_ms) const noexcept {
        return Sys_Wait_for_Condition_Timeout(id_, &check<condition>, timeout_ms, &out, sizeof(T), nullptr);
    }

    // Run handler (a function given as a template argument) for every
    // occurrence, in the system thread: costs what a C handler costs.
    template <Handler handler>
    Status subscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Subscribe_to_Event(id_, pid, &call<handler>, nullptr);
    }
    template <Handler handler>
    Status unsubscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call<handler>);
    }
    // A handler returning bool: false unsubscribes it.
    template <EndingHandler handler>
    Status subscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Subscribe_to_Event(id_, pid, &call_ending<handler>, nullptr);
    }
    template <EndingHandler handler>
    Status unsubscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call_ending<handler>);
    }

    // Run a lambda for every occurrence. Without captures, each lambda type
    // keeps its function pointer in one static (2 bytes on the AVR); with
    // captures (values or references, copied as bytes), a copy of them and
    // a context binding (6 bytes on the AVR, and a flag): one subscription
    // at a time per lambda (SYS_E_EXISTS for a second until it is
    // unsubscribed). A lambda returning bool unsubscribes itself with false.
    template <typename Lambda>
    Status subscribe(const Lambda &lambda, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        static_assert(detail::handles<Lambda, T>::value,
                      "the handler must be a lambda taking const T & of the event's data type "
                      "(openswarm.json's type for the app's events), returning void or bool");
        return subscribe_lambda(lambda, pid, detail::choice<captureless<Lambda>()>{});
    }
    template <typename Lambda>
    Status unsubscribe(const Lambda &, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return unsubscribe_lambda<Lambda>(pid, detail::choice<captureless<Lambda>()>{});
    }

    // Run method on object for every occurrence: the object is the
    // handler's context. One object per method at a time (SYS_E_EXISTS). A
    // method returning bool ends its subscription with false.
    template <typename Object, void (Object::*method)(const T &)>
    Status subscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, void, method>>::subscribe(id_, pid, &object);
    }
    template <typename Object, bool (Object::*method)(const T &)>
    Status subscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, bool, method>>::subscribe(id_, pid, &object);
    }
    template <typename Object, void (Object::*method)(const T &)>
    Status unsubscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, void, method>>::unsubscribe(id_, pid, &object);
    }
    template <typename Object, bool (Object::*method)(const T &)>
    Status unsubscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, bool, method>>::unsubscribe(id_, pid, &object);
    }

    // The data the last occurrence carried, if any is kept.
    Status last(T &out) const noexcept { return Sys_Get_EventData(id_, &out, sizeof(T), nullptr); }

  private:
    static const T &value_of(const sys_event_data *d) noexcept { return *static_cast<const T *>(d->value); }

    template <Handler handler>
    static bool call(sys_pid, sys_event_id, const sys_event_data *d) noexcept {
        handler(value_of(d));
        return true;
    }
    template <EndingHandler handler>
    static bool call_ending(sys_pid, sys_event_id, const sys_event_data *d) noexcept {
        return handler(value_of(d));
    }
    template <Condition condition>
    static bool check(const sys_event_data *d) noexcept {
        return condition(value_of(d));
    }
    // The function pointer a captureless lambda converts to.
    template <typename Lambda>
    using Pointer = decltype(detail::make<const Lambda &>()(detail::make<const T &>())) (*)(const T &);
    template <typename Lambda>
    static constexpr bool captureless() noexcept {
        return detail::converts<Lambda, Pointer<Lambda>>::value;
    }
    template <typename Lambda>
    struct Stored {
        static Pointer<Lambda> handler;
    };
    template <typename Lambda>
    static bool call_stored(sys_pid, sys_event_id, const sys_event_data *d) noexcept {
        return detail::call_handler(Stored<Lambda>::handler, value_of(d));
    }
    template <typename Lambda>
    Status subscribe_lambda(const Lambda &lambda, sys_pid pid, detail::choice<true>) const noexcept {
        Stored<Lambda>::handler = lambda; // a captureless lambda converts to its pointer
        return Sys_Subscribe_to_Event(id_, pid, &call_stored<Lambda>, nullptr);
    }
    template <typename Lambda>
    Status unsubscribe_lambda(sys_pid pid, detail::choice<true>) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call_stored<Lambda>);
    }

    // A lambda with captures: its bytes copied into a static of its type,
    // which is the handler's context.
    template <typename Lambda>
    struct Captured {
        static bool run(void *context, const sys_event_data *d) noexcept {
            return detail::call_handler(*static_cast<const Lambda *>(context), value_of(d));
        }
    };
    template <typename Lambda>
    Status subscribe_lambda(const Lambda &lambda, sys_pid pid, detail::choice<false>) const noexcept {
        return detail::subscribe_captures<Captured<Lambda>>(id_, pid, lambda);
    }
    template <typename Lambda>
    Status unsubscribe_lambda(sys_pid pid, detail::choice<false>) const noexcept {
        return detail::Bound<Captured<Lambda>>::unsubscribe(id_, pid, detail::Captures<Lambda>::bytes);
    }

    // A member function, its object the context.
    template <typename Object, typename R, R (Object::*method)(const T &)>
    struct Method {
        static bool run(void *context, const sys_event_data *d) noexcept {
            Object *object = static_cast<Object *>(context);
            return detail::call_handler([object](const T &v) { return (object->*method)(v); }, value_of(d));
        }
    };

    sys_event_id id_;
};

template <typename T>
template <typename Lambda>
typename Event<T>::template Pointer<Lambda> Event<T>::Stored<Lambda>::handler = nullptr;
// An event that carries no data (openswarm.json's "type": "none"). Its
// handlers take nothing; as Event<T>'s, they may be functions, lambdas
// (with or without captures) or methods, and one returning bool ends its
// own subscription with false.
template <>
class Event<void> {
  public:
    using Handler = void (*)();
    using EndingHandler = bool (*)();

    constexpr explicit Event(sys_event_id id) noexcept : id_(id) {}
    constexpr sys_event_id id() const noexcept { return id_; }

    Status enroll() const noexcept { return Sys_Register_Event_Sized(id_, 0); }
    Status send() const noexcept { return Sys_Send_Event(id_, nullptr, 0); }
    Status wait() const noexcept { return Sys_Wait_for_Event(id_, nullptr, 0, nullptr); }
    Status wait(uint32_t timeout_ms) const noexcept {
        return Sys_Wait_for_Event_Timeout(id_, timeout_ms, nullptr, 0, nullptr);
    }

    template <Handler handler>
    Status subscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Subscribe_to_Event(id_, pid, &call<Handler, handler>, nullptr);
    }
    template <Handler handler>
    Status unsubscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call<Handler, handler>);
    }
    template <EndingHandler handler>
    Status subscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Subscribe_to_Event(id_, pid, &call<EndingHandler, handler>, nullptr);
    }
    template <EndingHandler handler>
    Status unsubscribe(sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call<EndingHandler, handler>);
    }

    template <typename Lambda>
    Status subscribe(const Lambda &lambda, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        static_assert(detail::same<decltype(&Lambda::operator()), void (Lambda::*)() const>::value ||
                          detail::same<decltype(&Lambda::operator()), bool (Lambda::*)() const>::value,
                      "the handler of an event without data must be a lambda without parameters, "
                      "returning void or bool");
        return subscribe_lambda(lambda, pid, detail::choice<captureless<Lambda>()>{});
    }
    template <typename Lambda>
    Status unsubscribe(const Lambda &, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return unsubscribe_lambda<Lambda>(pid, detail::choice<captureless<Lambda>()>{});
    }

    template <typename Object, void (Object::*method)()>
    Status subscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, void, method>>::subscribe(id_, pid, &object);
    }
    template <typename Object, bool (Object::*method)()>
    Status subscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, bool, method>>::subscribe(id_, pid, &object);
    }
    template <typename Object, void (Object::*method)()>
    Status unsubscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, void, method>>::unsubscribe(id_, pid, &object);
    }
    template <typename Object, bool (Object::*method)()>
    Status unsubscribe(Object &object, sys_pid pid = SYS_PID_SYSTEM) const noexcept {
        return detail::Bound<Method<Object, bool, method>>::unsubscribe(id_, pid, &object);
    }

  private:
    template <typename F, F handler>
    static bool call(sys_pid, sys_event_id, const sys_event_data *) noexcept {
        return detail::call_handler(handler);
    }

    template <typename Lambda>
    using Pointer = decltype(detail::make<const Lambda &>()()) (*)();
    template <typename Lambda>
    static constexpr bool captureless() noexcept {
        return detail::converts<Lambda, Pointer<Lambda>>::value;
    }
    template <typename Lambda>
    struct Stored {
        static Pointer<Lambda> handler;
    };
    template <typename Lambda>
    static bool call_stored(sys_pid, sys_event_id, const sys_event_data *) noexcept {
        return detail::call_handler(Stored<Lambda>::handler);
    }
    template <typename Lambda>
    Status subscribe_lambda(const Lambda &lambda, sys_pid pid, detail::choice<true>) const noexcept {
        Stored<Lambda>::handler = lambda;
        return Sys_Subscribe_to_Event(id_, pid, &call_stored<Lambda>, nullptr);
    }
    template <typename Lambda>
    Status unsubscribe_lambda(sys_pid pid, detail::choice<true>) const noexcept {
        return Sys_Unsubscribe_from_Event(id_, pid, &call_stored<Lambda>);
    }

    template <typename Lambda>
    struct Captured {
        static bool run(void *context, const sys_event_data *) noexcept {
            return detail::call_handler(*static_cast<const Lambda *>(context));
        }
    };
    template <typename Lambda>
    Status subscribe_lambda(const Lambda &lambda, sys_pid pid, detail::choice<false>) const noexcept {
        return detail::subscribe_captures<Captured<Lambda>>(id_, pid, lambda);
    }
    template <typename Lambda>
    Status unsubscribe_lambda(sys_pid pid, detail::choice<false>) const noexcept {
        return detail::Bound<Captured<Lambda>>::unsubscribe(id_, pid, detail::Captures<Lambda>::bytes);
    }

    template <typename Object, typename R, R (Object::*method)()>
    struct Method {
        static bool run(void *context, const sys_event_data *) noexcept {
            Object *object = static_cast<Object *>(context);
            return detail::call_handler([object] { return (object->*method)(); });
        }
    };

    sys_event_id id_;
};

template <typename Lambda>
Event<void>::Pointer<Lambda> Event<void>::Stored<Lambda>::handler = nullptr;

// Threads.
struct Thread {
    // Start fn (a function or a lambda without captures) on a stack of
    // stack_bytes (0: the kernel's default).
    static Status start(void (*fn)(), uint16_t stack_bytes = 0, uint8_t priority = 0,
                        sys_pid *pid = nullptr) noexcept {
        union {
            void (*plain)();
            void *erased;
        } f;
        f.plain = fn;
        return Sys_Start_Process_Ex(&run, f.erased, stack_bytes, priority, pid);
    }
    static Status yield() noexcept { return Sys_Yield(); }
    static Status sleep(uint32_t ms) noexcept { return Sys_Sleep(ms); }
    static sys_pid self() noexcept { return Sys_Get_ProcessID(); }

  private:
    static void run(void *erased) noexcept {
        union {
            void (*plain)();
            void *erased;
        } f;
        f.erased = erased;
        f.plain();
    }
};

// No thread switch and no event dispatch while it lives.
class CriticalSection {
  public:
    CriticalSection() noexcept { Sys_Start_CriticalSection(); }
    ~CriticalSection() { Sys_End_CriticalSection(); }
    CriticalSection(const CriticalSection &) = delete;
    CriticalSection &operator=(const CriticalSection &) = delete;
};

inline uint32_t now_ms() noexcept { return Sys_Get_SystemTime(); }

}  // namespace openswarm

#endif
