/* robot.h on the e-puck2 under QEMU (qemu.console_printf): printf reaches
 * the board's console after robot_console_init() (newlib's _write), the
 * heap behind it only the small arena newlib's stream records need (a
 * malloc of 1 KB fails), and robot_id() is the run's --id=N. */
#include <stdio.h>
#include <stdlib.h>

#include "openswarm/robot.h"
#include "test_target.h"

void target_interrupt(int16_t value) { (void)value; } /* none asked for */

int main(void) {
    robot_console_init();
    printf("printf %d %s 0x%x\n", -42, "e-puck2", 0xBEEFu);
    printf("robot_id %u\n", (unsigned)robot_id());
    void *block = malloc(1024);
    printf("1 KB from the heap: %s\n", block == NULL ? "refused" : "given");
    target_exit(0);
}
