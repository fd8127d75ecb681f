/* The Cortex-M4's system control space: the registers this port uses
 * (ARMv7-M Architecture Reference Manual, B3). */
#ifndef CORTEX_M4_SYSTEM_CONTROL_H
#define CORTEX_M4_SYSTEM_CONTROL_H

#include <stdint.h>

#define SCS_REG(address) (*(volatile uint32_t *)(address))

#define SYST_CSR SCS_REG(0xE000E010u) /* SysTick control and status */
#define SYST_RVR SCS_REG(0xE000E014u) /* reload value */
#define SYST_CVR SCS_REG(0xE000E018u) /* current value */
#define SYST_CSR_ENABLE (1u << 0)
#define SYST_CSR_TICKINT (1u << 1)
#define SYST_CSR_CLKSOURCE_CPU (1u << 2)

#define NVIC_ISER(n) SCS_REG(0xE000E100u + 4u * (n))
#define NVIC_ICER(n) SCS_REG(0xE000E180u + 4u * (n))
#define NVIC_ISPR(n) SCS_REG(0xE000E200u + 4u * (n))
#define NVIC_IPR8(irq) (*(volatile uint8_t *)(0xE000E400u + (uint32_t)(irq)))

#define SCB_ICSR SCS_REG(0xE000ED04u)
#define SCB_ICSR_PENDSVSET (1u << 28)
#define SCB_ICSR_PENDSTSET (1u << 26) /* SysTick pending */
#define SCB_VTOR SCS_REG(0xE000ED08u)
#define SCB_CCR SCS_REG(0xE000ED14u)
#define SCB_CCR_DIV_0_TRP (1u << 4)
#define SCB_CCR_STKALIGN (1u << 9)
#define SCB_SHPR1 SCS_REG(0xE000ED18u) /* MemManage, BusFault, UsageFault */
#define SCB_SHPR2 SCS_REG(0xE000ED1Cu) /* SVCall in bits 31:24 */
#define SCB_SHPR3 SCS_REG(0xE000ED20u) /* PendSV 23:16, SysTick 31:24 */
#define SCB_SHCSR SCS_REG(0xE000ED24u)
#define SCB_SHCSR_SYSTICKACT (1u << 11) /* SysTick being handled */
#define SCB_SHCSR_FAULTS_ENABLE ((1u << 16) | (1u << 17) | (1u << 18)) /* Mem, Bus, Usage */
#define SCB_CFSR SCS_REG(0xE000ED28u)
#define SCB_HFSR SCS_REG(0xE000ED2Cu)
#define SCB_MMFAR SCS_REG(0xE000ED34u)
#define SCB_BFAR SCS_REG(0xE000ED38u)
#define SCB_CPACR SCS_REG(0xE000ED88u)
#define SCB_CPACR_FPU_FULL (0xFu << 20) /* CP10 and CP11 */
#define FPU_FPCCR SCS_REG(0xE000EF34u)
#define FPU_FPCCR_LAZY ((1u << 31) | (1u << 30)) /* ASPEN, LSPEN */

#endif
