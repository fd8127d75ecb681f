/* Sleep modes in the native mode: the kernel's idle sleeps the robot; a
 * program's own SLEEP is one instruction's time. */
#ifndef OPENSWARM_NATIVE_AVR_SLEEP_H
#define OPENSWARM_NATIVE_AVR_SLEEP_H

#define SLEEP_MODE_IDLE 0
#define SLEEP_MODE_PWR_DOWN 4
#define set_sleep_mode(mode) ((void)(mode))
#define sleep_enable() ((void)0)
#define sleep_disable() ((void)0)
#define sleep_cpu() ((void)0)
#define sleep_mode() ((void)0)

#endif
