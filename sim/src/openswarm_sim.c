/*
 * openswarm-sim: runs a robot's firmware ELF, cycle-exactly, in simavr.
 *
 * Copyright (c) 2026 The OpenSwarm authors.
 * This program is free software: you can redistribute it and/or modify it
 * under the terms of the GNU General Public License as published by the
 * Free Software Foundation, either version 3 of the License, or (at your
 * option) any later version. It links libsimavr (GPLv3).
 *
 * Conventions shared with the firmware (ports/kilobot/include/openswarm/kilobot_sim.h):
 *   GPIOR1  console: each byte written is a character, '\n' ends a line
 *   UART0   the robot's debug serial port, printed like the console
 *   GPIOR0  exit status, read when the firmware stops (SLEEP with
 *           interrupts disabled)
 *   GPIOR2  marker: with --marks, every change of its value is printed
 *           with the exact cycle, for cycle-exact measurements
 */
#include <errno.h>
#include <getopt.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <avr_adc.h>
#include <avr_eeprom.h>
#include <avr_ioport.h>
#include <avr_timer.h>
#include <avr_uart.h>
#include <sim_avr.h>
#include <sim_elf.h>
#include <sim_interrupts.h>
#include <sim_io.h>
#include <sim_gdb.h>
#include <sim_irq.h>
#include <sim_vcd_file.h>

#define GPIOR0_ADDR 0x3E
#define GPIOR1_ADDR 0x4A
#define GPIOR2_ADDR 0x4B
#define MAX_WATCHED_IRQS 8
#define EM_AVR 83

enum { EXIT_USAGE = 2, EXIT_CRASH = 3, EXIT_TIMEOUT = 4 };

typedef struct options {
    const char *elf;
    double seconds;
    int quiet;
    int expect_stop;
    int marks;
    int trace;
    const char *trace_csv;
    int gdb_port;       /* 0: no debugger */
    const char *vcd;
    int light_mv, voltage_mv, temperature_mv; /* ADC inputs, -1: 0 V */
    int uid;            /* -1: leave the EEPROM erased */
    int calibration[4]; /* turn left, turn right, straight left, straight right; -1: erased */
    int watched[MAX_WATCHED_IRQS];
    int n_watched;
} options;

typedef struct console {
    char line[256];
    size_t len;
} console;

static void usage(FILE *out) {
    fprintf(out,
            "usage: openswarm-sim [options] FIRMWARE.elf\n"
            "Run an AVR robot firmware in simavr, cycle-exactly, and print its console.\n\n"
            "  -t, --time SECONDS   simulated time to run (default 10)\n"
            "  -s, --expect-stop    fail (exit 4) unless the firmware stops by itself\n"
            "  -q, --quiet          do not print the console\n"
            "  -m, --marks          print 'mark VALUE CYCLE' when the firmware changes GPIOR2\n"
            "      --trace          print the robot's LED colour and motor duty changes\n"
            "      --trace-csv FILE write them as CSV: time_s,cycle,device,a,b,c\n"
            "      --light MV       ambient light sensor (ADC7) input, millivolts\n"
            "      --voltage MV     battery sense (ADC6) input, millivolts\n"
            "      --temperature MV internal temperature sensor input, millivolts\n"
            "      --gdb PORT       wait for avr-gdb on PORT (avr-gdb -ex 'target remote :PORT')\n"
            "      --vcd FILE       record LED pins, motor PWM and markers for GTKWave\n"
            "      --uid N          the robot's id (EEPROM 0xB0), 0..65535\n"
            "      --calibration TL,TR,SL,SR  motor duties to turn left, turn right and go\n"
            "                       straight (left and right motor), 0..255 each\n"
            "  -i, --watch-irq N    print 'irq N CYCLE' when interrupt vector N is raised\n"
            "  -h, --help           this text\n\n"
            "Exit status: the firmware's own status if it stopped, 0 if the time ran\n"
            "out (4 with --expect-stop), 2 bad usage or ELF, 3 the firmware crashed.\n");
}

static int parse(int argc, char **argv, options *o) {
    static const struct option longopts[] = {{"time", required_argument, 0, 't'},
                                             {"expect-stop", no_argument, 0, 's'},
                                             {"quiet", no_argument, 0, 'q'},
                                             {"marks", no_argument, 0, 'm'},
                                             {"trace", no_argument, 0, 'T'},
                                             {"trace-csv", required_argument, 0, 'C'},
                                             {"uid", required_argument, 0, 'U'},
                                             {"light", required_argument, 0, 'L'},
                                             {"voltage", required_argument, 0, 'V'},
                                             {"temperature", required_argument, 0, 'E'},
                                             {"gdb", required_argument, 0, 'G'},
                                             {"vcd", required_argument, 0, 'W'},
                                             {"calibration", required_argument, 0, 'K'},
                                             {"watch-irq", required_argument, 0, 'i'},
                                             {"help", no_argument, 0, 'h'},
                                             {0, 0, 0, 0}};
    o->seconds = 10.0;
    o->uid = -1;
    o->light_mv = o->voltage_mv = o->temperature_mv = -1;
    for (int i = 0; i < 4; i++) o->calibration[i] = -1;
    int c;
    while ((c = getopt_long(argc, argv, "t:sqmi:h", longopts, NULL)) != -1) {
        switch (c) {
        case 't': {
            char *end;
            o->seconds = strtod(optarg, &end);
            if (*end == 's') end++;
            if (*end != '\0' || o->seconds <= 0) {
                fprintf(stderr, "openswarm-sim: --time '%s': expected seconds, e.g. --time 2.5\n",
                        optarg);
                return -1;
            }
            break;
        }
        case 's': o->expect_stop = 1; break;
        case 'q': o->quiet = 1; break;
        case 'm': o->marks = 1; break;
        case 'T': o->trace = 1; break;
        case 'C': o->trace_csv = optarg; break;
        case 'L':
        case 'V':
        case 'E':
        case 'G': {
            char *end;
            long v = strtol(optarg, &end, 10);
            long max = c == 'G' ? 65535 : 5000;
            if (*end != '\0' || v < (c == 'G' ? 1 : 0) || v > max) {
                fprintf(stderr, "openswarm-sim: '%s': expected %s\n", optarg,
                        c == 'G' ? "a TCP port 1..65535, e.g. --gdb 1234"
                                 : "millivolts 0..5000, e.g. --light 1650");
                return -1;
            }
            if (c == 'L') o->light_mv = (int)v;
            if (c == 'V') o->voltage_mv = (int)v;
            if (c == 'E') o->temperature_mv = (int)v;
            if (c == 'G') o->gdb_port = (int)v;
            break;
        }
        case 'W': o->vcd = optarg; break;
        case 'U': {
            char *end;
            long v = strtol(optarg, &end, 0);
            if (*end != '\0' || v < 0 || v > 65535) {
                fprintf(stderr, "openswarm-sim: --uid '%s': expected a number 0..65535\n", optarg);
                return -1;
            }
            o->uid = (int)v;
            break;
        }
        case 'K': {
            int v[4];
            char extra;
            if (sscanf(optarg, "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &extra) != 4 ||
                v[0] < 0 || v[0] > 255 || v[1] < 0 || v[1] > 255 || v[2] < 0 || v[2] > 255 ||
                v[3] < 0 || v[3] > 255) {
                fprintf(stderr, "openswarm-sim: --calibration '%s': expected four duties 0..255, "
                                "e.g. --calibration 70,70,65,68\n", optarg);
                return -1;
            }
            for (int i = 0; i < 4; i++) o->calibration[i] = v[i];
            break;
        }
        case 'i': {
            char *end;
            long v = strtol(optarg, &end, 10);
            if (*end != '\0' || v < 1 || v > 255 || o->n_watched == MAX_WATCHED_IRQS) {
                fprintf(stderr, "openswarm-sim: --watch-irq '%s': expected a vector number 1..255 "
                                "(at most %d of them)\n", optarg, MAX_WATCHED_IRQS);
                return -1;
            }
            o->watched[o->n_watched++] = (int)v;
            break;
        }
        case 'h': usage(stdout); exit(0);
        default: usage(stderr); return -1;
        }
    }
    if (optind != argc - 1) {
        fprintf(stderr, "openswarm-sim: expected one FIRMWARE.elf (see --help)\n");
        return -1;
    }
    o->elf = argv[optind];
    return 0;
}

/* Check the file before simavr sees it: simavr 1.6 crashes on some bad
 * input instead of reporting it. */
static int check_elf(const char *path) {
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "openswarm-sim: %s: %s\n", path, strerror(errno));
        return -1;
    }
    unsigned char h[20];
    size_t n = fread(h, 1, sizeof h, f);
    fclose(f);
    if (n < sizeof h || memcmp(h, "\177ELF", 4) != 0) {
        fprintf(stderr, "openswarm-sim: %s: not an ELF file (build the firmware first)\n", path);
        return -1;
    }
    if ((h[18] | h[19] << 8) != EM_AVR) {
        fprintf(stderr, "openswarm-sim: %s: an ELF for another CPU, not AVR "
                        "(build it with the Kilobot toolchain)\n", path);
        return -1;
    }
    return 0;
}

static void console_char(console *c, uint8_t v);

static void console_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    avr->data[addr] = v;
    console_char(param, v);
}

static void console_char(console *c, uint8_t v) {
    if (v == '\n' || c->len == sizeof c->line - 1) {
        c->line[c->len] = '\0';
        fprintf(stdout, "%s\n", c->line);
        fflush(stdout);
        c->len = 0;
    } else if (v != '\r') {
        c->line[c->len++] = (char)v;
    }
}

static void uart_output(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    console_char(param, (uint8_t)value);
}

static void console_drop(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    (void)param;
    avr->data[addr] = v;
}

static void mark_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    (void)param;
    if (avr->data[addr] != v)
        printf("mark %u %llu\n", (unsigned)v, (unsigned long long)avr->cycle);
    avr->data[addr] = v;
}

/* ---- the Kilobot's LED and motors, as the robot shows them ---- */

/* A colour or a duty pair is written one register at a time; what the
 * robot shows is the state once the writes settle, so changes are reported
 * after SETTLE_CYCLES of quiet, stamped with the time the burst began. */
#define SETTLE_CYCLES 200

typedef struct robot_trace {
    avr_t *avr;
    int print;
    FILE *csv;
    uint8_t ddrc, ddrd;
    uint8_t pwm[2];           /* left (OC2A), right (OC2B) */
    int shown_rgb;            /* last reported, -1 before the first */
    int shown_pwm[2];
    avr_cycle_count_t burst;  /* cycle of the first unreported change, 0: none */
} robot_trace;


static void trace_emit(robot_trace *t, const char *device, int a, int b, int c) {
    double s = (double)t->burst / (double)t->avr->frequency;
    if (t->print) {
        if (c >= 0)
            printf("[%10.6f s] %-6s red %d green %d blue %d\n", s, device, a, b, c);
        else
            printf("[%10.6f s] %-6s left %d right %d\n", s, device, a, b);
        fflush(stdout);
    }
    if (t->csv)
        fprintf(t->csv, "%.6f,%llu,%s,%d,%d,%d\n", s, (unsigned long long)t->burst, device, a,
                b, c < 0 ? 0 : c);
}

static int led_rgb(const robot_trace *t, int *r, int *g, int *b) {
    *r = ((t->ddrd >> 5) & 1) | (((t->ddrd >> 4) & 1) << 1);
    *g = ((t->ddrc >> 3) & 1) | (((t->ddrc >> 2) & 1) << 1);
    *b = ((t->ddrc >> 5) & 1) | (((t->ddrc >> 4) & 1) << 1);
    return *r | *g << 2 | *b << 4;
}

static avr_cycle_count_t settled(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    (void)when;
    robot_trace *t = param;
    int r, g, b;
    int rgb = led_rgb(t, &r, &g, &b);
    if (rgb != t->shown_rgb) {
        t->shown_rgb = rgb;
        trace_emit(t, "led", r, g, b);
    }
    if (t->pwm[0] != t->shown_pwm[0] || t->pwm[1] != t->shown_pwm[1]) {
        t->shown_pwm[0] = t->pwm[0];
        t->shown_pwm[1] = t->pwm[1];
        trace_emit(t, "motors", t->pwm[0], t->pwm[1], -1);
    }
    t->burst = 0;
    return 0;
}

static void changed(robot_trace *t) {
    if (t->burst == 0) t->burst = t->avr->cycle;
    avr_cycle_timer_cancel(t->avr, settled, t);
    avr_cycle_timer_register(t->avr, SETTLE_CYCLES, settled, t);
}

static void ddrc_changed(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->ddrc = (uint8_t)value;
    changed(t);
}

static void ddrd_changed(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    robot_trace *t = param;
    t->ddrd = (uint8_t)value;
    changed(t);
}

static void pwm_changed(robot_trace *t, int motor, uint32_t value) {
    t->pwm[motor] = (uint8_t)value;
    changed(t);
}

static void left_pwm(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    pwm_changed(param, 0, value);
}

static void right_pwm(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    pwm_changed(param, 1, value);
}

static void trace_robot(avr_t *avr, robot_trace *t) {
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('C'), IOPORT_IRQ_DIRECTION_ALL),
                            ddrc_changed, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_DIRECTION_ALL),
                            ddrd_changed, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM0),
                            left_pwm, t);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM1),
                            right_pwm, t);
}

/* The robot's identity and calibration, where kilolib reads them. */
static void write_eeprom(avr_t *avr, uint16_t address, const uint8_t *bytes, uint32_t n) {
    avr_eeprom_desc_t d = {(uint8_t *)bytes, address, n};
    avr_ioctl(avr, AVR_IOCTL_EEPROM_SET, &d);
}

/* The Kilobot's analog inputs: simavr converts millivolts against AVcc. */
#define KILOBOT_AVCC_MV 3300

static void set_analog(avr_t *avr, int channel, int millivolts) {
    if (millivolts >= 0)
        avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, channel), (uint32_t)millivolts);
}

static void configure_robot(avr_t *avr, const options *o) {
    avr->vcc = avr->avcc = avr->aref = KILOBOT_AVCC_MV;
    set_analog(avr, ADC_IRQ_ADC7, o->light_mv);
    set_analog(avr, ADC_IRQ_ADC6, o->voltage_mv);
    set_analog(avr, ADC_IRQ_TEMP, o->temperature_mv);
    static const uint16_t calibration_address[4] = {0x05, 0x09, 0x0C, 0x14};
    for (int i = 0; i < 4; i++) {
        if (o->calibration[i] < 0) continue;
        uint8_t v = (uint8_t)o->calibration[i];
        write_eeprom(avr, calibration_address[i], &v, 1);
    }
    if (o->uid >= 0) {
        uint8_t uid[2] = {(uint8_t)(o->uid & 0xFF), (uint8_t)(o->uid >> 8)};
        write_eeprom(avr, 0xB0, uid, 2);
    }
}

typedef struct watched_irq {
    avr_t *avr;
    int vector;
} watched_irq;

static void irq_raised(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    const watched_irq *w = param;
    if (value) printf("irq %d %llu\n", w->vector, (unsigned long long)w->avr->cycle);
}

/* simavr reports what it loads at its lowest level; keep its errors only. */
static void log_errors_only(avr_t *avr, const int level, const char *format, va_list args) {
    (void)avr;
    if (level > LOG_ERROR) return;
    if (level == LOG_OUTPUT) return;
    vfprintf(stderr, format, args);
}

/* Sleeping costs no wall-clock time: simavr has already advanced the cycle
 * counter to the next timer event. */
static void fast_forward(avr_t *avr, avr_cycle_count_t how_long) {
    (void)avr;
    (void)how_long;
}

int main(int argc, char **argv) {
    options o = {0};
    if (parse(argc, argv, &o) != 0) return EXIT_USAGE;
    if (check_elf(o.elf) != 0) return EXIT_USAGE;

    avr_global_logger_set(log_errors_only);
    elf_firmware_t fw;
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(o.elf, &fw) != 0) {
        fprintf(stderr, "openswarm-sim: %s: cannot read the firmware\n", o.elf);
        return EXIT_USAGE;
    }
    if (fw.mmcu[0] == '\0' || fw.frequency == 0) {
        fprintf(stderr, "openswarm-sim: %s: no MCU record in the ELF; link it with the OpenSwarm "
                        "port (it adds ports/kilobot/src/mcu_tag.c)\n", o.elf);
        return EXIT_USAGE;
    }
    avr_t *avr = avr_make_mcu_by_name(fw.mmcu);
    if (avr == NULL) {
        fprintf(stderr, "openswarm-sim: %s: simavr does not know the MCU '%s'\n", o.elf, fw.mmcu);
        return EXIT_USAGE;
    }
    avr_init(avr);
    avr->log = LOG_ERROR;
    avr_load_firmware(avr, &fw);
    avr->sleep = fast_forward;
    configure_robot(avr, &o);

    console con = {{0}, 0};
    avr_register_io_write(avr, GPIOR1_ADDR, o.quiet ? console_drop : console_write, &con);
    static console serial = {{0}, 0};
    if (!o.quiet)
        avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                                uart_output, &serial);
    if (o.marks) avr_register_io_write(avr, GPIOR2_ADDR, mark_write, NULL);
    static watched_irq watches[MAX_WATCHED_IRQS];
    for (int i = 0; i < o.n_watched; i++) {
        watches[i].avr = avr;
        watches[i].vector = o.watched[i];
        avr_irq_t *irq = avr_get_interrupt_irq(avr, (uint8_t)o.watched[i]);
        if (irq == NULL) {
            fprintf(stderr, "openswarm-sim: --watch-irq %d: %s has no such interrupt vector\n",
                    o.watched[i], fw.mmcu);
            return EXIT_USAGE;
        }
        avr_irq_register_notify(irq, irq_raised, &watches[i]);
    }

    /* The robot starts dark and still: only changes are reported. */
    robot_trace trace = {avr, o.trace, NULL, 0, 0, {0, 0}, 0, {0, 0}, 0};
    if (o.trace_csv != NULL) {
        trace.csv = fopen(o.trace_csv, "w");
        if (trace.csv == NULL) {
            fprintf(stderr, "openswarm-sim: --trace-csv %s: %s\n", o.trace_csv, strerror(errno));
            return EXIT_USAGE;
        }
        fprintf(trace.csv, "time_s,cycle,device,a,b,c\n");
    }
    if (o.trace || trace.csv != NULL) trace_robot(avr, &trace);

    static avr_vcd_t vcd;
    if (o.vcd != NULL) {
        if (avr_vcd_init(avr, o.vcd, &vcd, 1000) != 0) {
            fprintf(stderr, "openswarm-sim: --vcd %s: cannot create the file\n", o.vcd);
            return EXIT_USAGE;
        }
        avr_vcd_add_signal(&vcd, avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('C'), IOPORT_IRQ_DIRECTION_ALL), 8, "ddrc_led_green_blue");
        avr_vcd_add_signal(&vcd, avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_DIRECTION_ALL), 8, "ddrd_led_red");
        avr_vcd_add_signal(&vcd, avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM0), 8, "motor_left");
        avr_vcd_add_signal(&vcd, avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM1), 8, "motor_right");
        avr_vcd_start(&vcd);
    }
    if (o.gdb_port != 0) {
        avr->gdb_port = o.gdb_port;
        avr->state = cpu_Stopped;
        avr_gdb_init(avr);
        fprintf(stderr, "openswarm-sim: waiting for avr-gdb: avr-gdb -ex 'target remote :%d' %s\n",
                o.gdb_port, o.elf);
    }

    avr_cycle_count_t limit = (avr_cycle_count_t)(o.seconds * (double)avr->frequency);
    int state = cpu_Running;
    while (avr->cycle < limit) {
        state = avr_run(avr);
        if (state == cpu_Done || state == cpu_Crashed) break;
    }
    if (trace.csv != NULL) fclose(trace.csv);
    if (o.vcd != NULL) avr_vcd_close(&vcd);
    double t = (double)avr->cycle / (double)avr->frequency;
    if (state == cpu_Crashed) {
        fprintf(stderr, "openswarm-sim: the firmware crashed at %.6f s (PC 0x%04x): a bad jump "
                        "or a stack overflow; run it with avr-gdb to see where\n",
                t, (unsigned)avr->pc);
        return EXIT_CRASH;
    }
    if (state == cpu_Done) {
        int status = avr->data[GPIOR0_ADDR];
        if (!o.quiet) fprintf(stderr, "openswarm-sim: stopped at %.6f s, status %d\n", t, status);
        return status;
    }
    if (o.expect_stop) {
        fprintf(stderr, "openswarm-sim: the firmware did not stop within %.3f s of simulated "
                        "time (PC 0x%04x%s); give it longer with --time\n", o.seconds,
                (unsigned)avr->pc, avr->state == cpu_Sleeping ? ", sleeping" : "");
        return EXIT_TIMEOUT;
    }
    if (!o.quiet) fprintf(stderr, "openswarm-sim: ran %.3f s of simulated time\n", t);
    return 0;
}
