/* Host port: the kernel's generic pool sizes suit it (no overrides). */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H
#endif
