/* The HAL framework: devices, their processors, and the path of a value
 * from a lower layer to an event and from an event to a lower layer. */
#include "kernel_internal.h"

#include <string.h>

static sys_device *devices[OS_CFG_MAX_DEVICES];

void os_hal_reset(void) { memset(devices, 0, sizeof devices); }

/* Run processor (or copy when there is none) into out. False if nothing is
 * to be emitted: the processor declined, or the value does not fit (both
 * counted in dev->rejected). */
static bool process(sys_device *dev, sys_processor processor, const void *in, uint8_t size,
                    uint8_t *out, uint8_t *out_size) {
    uint8_t n = size;
    if (processor != NULL)
        n = processor(dev, in, size, out, OS_CFG_HAL_MAX_VALUE);
    else if (size <= OS_CFG_HAL_MAX_VALUE && size != 0)
        memcpy(out, in, size);
    if ((processor != NULL && n == 0) || n > OS_CFG_HAL_MAX_VALUE) {
        port_irq_state_t s = port_irq_save(); /* 16 bits: not atomic on 8-bit CPUs */
        dev->rejected++;
        port_irq_restore(s);
        return false;
    }
    *out_size = n;
    return true;
}

static sys_device *device_for_command(sys_event_id event) {
    for (unsigned i = 0; i < OS_CFG_MAX_DEVICES; i++) {
        sys_device *d = devices[i];
        if (d == NULL) continue;
        if ((d->kind == SYS_DEVICE_OUTPUT && d->event == event) ||
            (d->kind == SYS_DEVICE_COMM && d->tx_event == event))
            return d;
    }
    return NULL;
}

/* Output and Tx path, subscribed in the system thread. */
static bool command_handler(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    sys_device *dev = device_for_command(event);
    if (dev == NULL) return false;
    uint8_t raw[OS_CFG_HAL_MAX_VALUE];
    uint8_t n;
    sys_processor p = dev->kind == SYS_DEVICE_COMM ? dev->tx_processor : dev->processor;
    if (process(dev, p, data->value, data->size, raw, &n) && dev->write != NULL)
        dev->write(dev, raw, n);
    return true;
}

/* Register event with room for any device value unless it is already;
 * *made says whether this call registered it (to undo on a later failure).
 * Interrupts are masked (register_device): the table is read as it is. */
static sys_status ensure_registered(sys_event_id event, bool *made) {
    *made = !os_event_registered(event);
    return *made ? Sys_Register_Event_Sized(event, OS_CFG_HAL_MAX_VALUE) : SYS_OK;
}

/* The event whose data an output or comm device writes out. */
static sys_event_id command_event(const sys_device *dev) {
    return dev->kind == SYS_DEVICE_COMM ? dev->tx_event : dev->event;
}

static int device_index(const sys_device *dev) {
    for (unsigned i = 0; i < OS_CFG_MAX_DEVICES; i++)
        if (devices[i] == dev) return (int)i;
    return -1;
}

/* The events a registration made, undone if a later step fails: a refused
 * device leaves the kernel as it found it. */
static void unregister_new(sys_event_id event, bool made) {
    if (made) Sys_Unregister_Event(event);
}

static sys_status register_device(sys_device *dev) {
    if (device_index(dev) >= 0) return SYS_E_EXISTS;
    /* One command event drives one device: a second would never be written. */
    if (dev->kind != SYS_DEVICE_INPUT &&
        device_for_command(command_event(dev)) != NULL)
        return SYS_E_EXISTS;
    int slot = device_index(NULL);
    if (slot < 0) {
        os_count(&os_stats.device_table_full);
        return SYS_E_POOL_FULL;
    }
    bool new_event = false, new_tx = false;
    sys_status st = ensure_registered(dev->event, &new_event);
    if (st == SYS_OK && dev->kind == SYS_DEVICE_COMM) st = ensure_registered(dev->tx_event, &new_tx);
    if (st == SYS_OK && dev->kind != SYS_DEVICE_INPUT) {
        st = Sys_Subscribe_to_Event(command_event(dev), SYS_PID_SYSTEM, command_handler, NULL);
        if (st == SYS_E_EXISTS) st = SYS_OK;
    }
    if (st != SYS_OK) {
        unregister_new(dev->event, new_event);
        unregister_new(dev->tx_event, new_tx);
        return st;
    }
    devices[slot] = dev;
    return SYS_OK;
}

/* Registration changes tables an interrupt may read: it runs with
 * interrupts masked (the kernel calls it makes nest their own masking). */
sys_status Sys_Register_Device(sys_device *dev) {
    if (dev == NULL || dev->kind > SYS_DEVICE_COMM) return SYS_E_INVALID;
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    sys_status st = register_device(dev);
    port_irq_restore(s);
    return st;
}

sys_status Sys_Unregister_Device(sys_device *dev) {
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    int slot = device_index(dev);
    if (dev == NULL || slot < 0) {
        port_irq_restore(s);
        return SYS_E_NOT_FOUND;
    }
    devices[slot] = NULL;
    if (dev->kind != SYS_DEVICE_INPUT) {
        sys_event_id command = command_event(dev);
        if (device_for_command(command) == NULL)
            Sys_Unsubscribe_from_Event(command, SYS_PID_SYSTEM, command_handler);
    }
    port_irq_restore(s);
    return SYS_OK;
}

sys_status Sys_Set_Processor(sys_device *dev, sys_processor processor, void *params) {
    if (dev == NULL) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save(); /* a lower-layer ISR may be using it */
    dev->processor = processor;
    dev->params = params;
    port_irq_restore(s);
    return SYS_OK;
}

sys_status Sys_Set_TxProcessor(sys_device *dev, sys_processor processor) {
    if (dev == NULL || dev->kind != SYS_DEVICE_COMM) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    dev->tx_processor = processor;
    port_irq_restore(s);
    return SYS_OK;
}

sys_status Sys_Device_Read(sys_device *dev, const void *raw, uint8_t size, void *value,
                           uint8_t capacity, uint8_t *value_size) {
    if (dev == NULL || dev->kind == SYS_DEVICE_OUTPUT || (raw == NULL && size != 0) ||
        (value == NULL && capacity != 0))
        return SYS_E_INVALID;
    uint8_t made[OS_CFG_HAL_MAX_VALUE];
    uint8_t n;
    if (!process(dev, dev->processor, raw, size, made, &n)) return SYS_E_NOT_FOUND;
    if (capacity != 0) memcpy(value, made, n < capacity ? n : capacity);
    if (value_size != NULL) *value_size = n;
    return Sys_Send_Event(dev->event, made, n);
}

sys_status Sys_Device_Input(sys_device *dev, const void *raw, uint8_t size) {
    sys_status st = Sys_Device_Read(dev, raw, size, NULL, 0, NULL);
    return st == SYS_E_NOT_FOUND ? SYS_OK : st; /* the processor chose to emit nothing */
}
