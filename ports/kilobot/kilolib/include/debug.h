/* Debug output over the Kilobot's serial port (38400 baud, 8N1 on PD1),
 * as with the classic library: call debug_init() once, then printf. The
 * simulator prints it like the console. */
#ifndef KILOLIB_DEBUG_H
#define KILOLIB_DEBUG_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

void debug_init(void);

#ifdef __cplusplus
}
#endif

#endif
