/* The analog sensors as HAL input devices: ambient light (ADC7), battery
 * voltage (ADC6) and the MCU's temperature sensor. A reading is taken when
 * asked (kilobot_sense) or every period (kilobot_sense_every, from the 1 ms
 * tick); its ADC count goes through the device's pre-processor, which makes
 * the int16_t its event carries (no processor: the count itself). */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"

#include "devices_internal.h"

#define SENSORS 3u

sys_device kilobot_light = {
    "light", SYS_DEVICE_INPUT, KILOBOT_EVENT_LIGHT, 0, NULL, NULL, NULL, NULL, 0};
sys_device kilobot_voltage = {
    "voltage", SYS_DEVICE_INPUT, KILOBOT_EVENT_VOLTAGE, 0, NULL, NULL, NULL, NULL, 0};
sys_device kilobot_temperature = {
    "temperature", SYS_DEVICE_INPUT, KILOBOT_EVENT_TEMPERATURE, 0, NULL, NULL, NULL, NULL, 0};

/* Periodic sampling, counted down by the tick: period 0 = off. Linked only
 * into applications that call kilobot_sense_every. */
static uint16_t period_ms[SENSORS], due_in_ms[SENSORS];

/* Comparisons rather than a table of pointers: a const table would be
 * copied to RAM on this MCU. SENSORS if d is not one of them. */
static uint8_t index_of(const sys_device *d) {
    return d == &kilobot_light         ? 0u
           : d == &kilobot_voltage     ? 1u
           : d == &kilobot_temperature ? 2u
                                       : SENSORS;
}

static sys_device *sensor_at(uint8_t i) {
    return i == 0u ? &kilobot_light : i == 1u ? &kilobot_voltage : &kilobot_temperature;
}

static uint8_t adc_input_at(uint8_t i) {
    return i == 0u ? KILOBOT_ADC_LIGHT : i == 1u ? KILOBOT_ADC_VOLTAGE : KILOBOT_ADC_TEMPERATURE;
}

/* The events keep two bytes each, not the HAL's OS_CFG_HAL_MAX_VALUE. */
sys_status kilobot_sensors_init(void) {
    sys_status st = SYS_OK;
    for (uint8_t i = 0; i < SENSORS && st == SYS_OK; i++) {
        sys_device *d = sensor_at(i);
        if (!Sys_IsEventRegistered(d->event))
            st = Sys_Register_Event_Sized(d->event, sizeof(int16_t));
        if (st == SYS_OK) st = Sys_Register_Device(d);
    }
    return st;
}

/* A busy ADC (-1) is tried again: the IR receiver takes it only at a
 * frame's start and decodes the whole frame in its interrupt, so the next
 * try comes after that frame; a conversion running at the try (the IR
 * receiver's or another reader's) ends within 104 us. In an interrupt
 * nothing takes the ADC midway. */
static int16_t read_adc(uint8_t input) {
    int16_t raw;
    while ((raw = kilobot_adc_read(input)) < 0) {
    }
    return raw;
}

/* The caller gets the value the processor made as well as the event. */
sys_status kilobot_sense(sys_device *sensor, int16_t *value) {
    uint8_t i = index_of(sensor);
    if (i == SENSORS) return SYS_E_INVALID;
    int16_t raw = read_adc(adc_input_at(i));
    return Sys_Device_Read(sensor, &raw, sizeof raw, value, value != NULL ? sizeof *value : 0, NULL);
}

/* Interrupt context, every 1 ms while any sensor has a period. */
static void sample_due(void) {
    for (uint8_t i = 0; i < SENSORS; i++) {
        if (period_ms[i] == 0u || --due_in_ms[i] != 0u) continue;
        due_in_ms[i] = period_ms[i];
        kilobot_sense(sensor_at(i), NULL);
    }
}

sys_status kilobot_sense_every(sys_device *sensor, uint16_t period) {
    uint8_t i = index_of(sensor);
    if (i == SENSORS) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    period_ms[i] = due_in_ms[i] = period;
    bool any = (period_ms[0] | period_ms[1] | period_ms[2]) != 0u;
    kilobot_sensors_tick_hook = any ? sample_due : NULL;
    port_irq_restore(s);
    return SYS_OK;
}
