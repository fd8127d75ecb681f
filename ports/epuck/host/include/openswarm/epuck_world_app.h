/* An e-puck app built for the world simulator (openswarm_add_firmware's
 * PORT epuck_world) keeps its main, renamed: its sources are compiled with
 * -Dmain=openswarm_robot_main and this header included first, so that the
 * process's own main (the world link) can run it on the simulated CPU.
 * The declaration gives it C linkage in a C++ app too. */
#ifndef OPENSWARM_EPUCK_WORLD_APP_H
#define OPENSWARM_EPUCK_WORLD_APP_H

#ifdef __cplusplus
extern "C" {
#endif

int openswarm_robot_main(void);

#ifdef __cplusplus
}
#endif

#endif
