/* {{name}}, without the OS: the hardware-near baseline of the paper's case
 * study (Gauci et al. 2014). One loop: wait for a frame, judge what is
 * straight ahead with the same classifier, set the wheels to that case's
 * speeds. No kernel, no events, no processors - and so no safety processor
 * between the controller and the steppers. */
#include "openswarm/epuck_plain.h"

int main(void) {
    static const epuck_wheel_speeds speeds_for[] = {
        [EPUCK_SEEN_NOTHING] = {550, 990},
        [EPUCK_SEEN_ROBOT] = {890, 530},
        [EPUCK_SEEN_OBJECT] = {980, 500},
    };
    epuck_plain_start();
    for (;;) {
        epuck_seen seen;
        if (!epuck_classify_frame(epuck_plain_wait_frame(), &seen)) continue;
        epuck_plain_set_wheels(speeds_for[seen].left, speeds_for[seen].right);
    }
}
