// The register model's hook for drivers that wait on the hardware: each
// time round a driver's wait (STM32_POLL in stm32f4_registers.h) the test's
// silicon runs, and does what the peripheral would have done meanwhile.
#pragma once

#include <cstdint>
#include <functional>

extern std::function<void()> epuck2_model_silicon;
extern uint64_t epuck2_model_polls; // waits' turns since the test reset it
