// The register model's hook for drivers that wait on the hardware: each
// time round a driver's wait (STM32_POLL in stm32f4_registers.h) the test's
// silicon runs, and does what the peripheral would have done meanwhile.
#pragma once

#include <cstdint>
#include <functional>

extern std::function<void()> epuck2_model_silicon;
extern uint64_t epuck2_model_polls; // waits' turns since the test reset it

// A GPIO port's BSRR write applied to ODR, as the port does at once
// (set bits 0-15, reset bits 16-31), BSRR read back as 0.
struct stm32_gpio;
void epuck2_model_apply_bsrr(stm32_gpio &port);
