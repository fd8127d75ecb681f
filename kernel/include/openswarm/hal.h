/* Hardware abstraction: each device is a module with a hardware-specific
 * lower layer and a processor that can be replaced at run time.
 *
 *   input:   lower layer --raw--> pre-processor --value--> event
 *   output:  event --command--> post-processor --raw--> lower layer
 *   comm:    lower layer --frame--> Rx processor --payload--> event
 *            event --payload--> Tx processor --frame--> lower layer
 *
 * A processor may keep state and parameters (dev->params), reject a value
 * (return 0: counted in dev->rejected) or override it (a safety limit).
 * A virtual sensor is a pre-processor that turns a rich reading (a camera
 * frame) into a simple value (the colour in front of the robot). */
#ifndef OPENSWARM_HAL_H
#define OPENSWARM_HAL_H

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sys_device_kind {
    SYS_DEVICE_INPUT = 0,
    SYS_DEVICE_OUTPUT,
    SYS_DEVICE_COMM
} sys_device_kind;

typedef struct sys_device sys_device;

/* Transform in (in_size bytes) into out (at most out_capacity bytes);
 * return the number of bytes written, 0 to emit nothing. */
typedef uint8_t (*sys_processor)(sys_device *dev, const void *in, uint8_t in_size, void *out,
                                 uint8_t out_capacity);
/* Lower layer: apply a raw value to the hardware / transmit a frame. */
typedef void (*sys_device_write)(sys_device *dev, const void *raw, uint8_t size);

struct sys_device {
    const char *name;
    sys_device_kind kind;
    sys_event_id event;         /* input: emitted; output: command; comm: received */
    sys_event_id tx_event;      /* comm: payloads to transmit */
    sys_processor processor;    /* input: pre-, output: post-, comm: Rx (NULL = copy) */
    sys_processor tx_processor; /* comm: Tx (NULL = copy) */
    sys_device_write write;     /* output and comm */
    void *params;               /* the processor's parameters */
    uint16_t rejected;          /* values a processor returned 0 for */
};

/* Register dev and the events it uses (with OS_CFG_HAL_MAX_VALUE bytes of
 * capacity when not registered yet); outputs subscribe in the system thread.
 * SYS_E_EXISTS if dev, or another device on its command event, is registered. */
sys_status Sys_Register_Device(sys_device *dev);
sys_status Sys_Unregister_Device(sys_device *dev);

/* Replace a device's processor (and its parameters) at run time. */
sys_status Sys_Set_Processor(sys_device *dev, sys_processor processor, void *params);
sys_status Sys_Set_TxProcessor(sys_device *dev, sys_processor processor);

/* Called by an input or comm device's lower layer (interrupt or thread)
 * with a raw reading or a received frame. */
sys_status Sys_Device_Input(sys_device *dev, const void *raw, uint8_t size);

/* Sys_Device_Input for a lower layer whose caller asked for the reading:
 * the value the processor made is sent and also copied to value (at most
 * capacity bytes; *value_size: its whole size, if value_size is not NULL).
 * SYS_E_NOT_FOUND if the processor emitted nothing (counted). */
sys_status Sys_Device_Read(sys_device *dev, const void *raw, uint8_t size, void *value,
                           uint8_t capacity, uint8_t *value_size);

#ifdef __cplusplus
}
#endif

#endif
