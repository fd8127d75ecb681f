/* What the device layer's files share, and no app needs. */
#ifndef EPUCK_DEVICES_INTERNAL_H
#define EPUCK_DEVICES_INTERNAL_H

#include "openswarm/epuck.h"

/* Each boot starts from standing wheels and no selector reading. */
void epuck_wheels_forget(void);
void epuck_selector_forget(void);

uint8_t epuck_selector_changes(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity);

#endif
