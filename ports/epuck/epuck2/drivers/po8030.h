/* The e-puck2's image sensor, a PO8030 (640 x 480): its master clock from
 * TIM5, its registers written over I2C so that it delivers the whole view
 * subsampled by 4, 160 x 120 pixels, as RGB565 (high byte first). */
#ifndef EPUCK2_PO8030_H
#define EPUCK2_PO8030_H

#include <stdbool.h>

#define EPUCK2_CAMERA_WIDTH 160u
#define EPUCK2_CAMERA_HEIGHT 120u

/* The clock started, then the registers written (the I2C master must be
 * initialised); false at the first write the sensor did not take. */
bool epuck2_po8030_init(void);

#endif
