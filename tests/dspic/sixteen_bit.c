/* The check's compiler has XC16's sizes, or it proves nothing about the
 * port; and the context has the layout switch.s and traps.s read. */
#include "openswarm/port_arch.h"

_Static_assert(sizeof(int) == 2, "int is 16 bits, as on XC16");
_Static_assert(sizeof(void *) == 2, "data pointers are 16 bits, as on XC16");
_Static_assert(sizeof(void (*)(void)) == 2, "function pointers are 16 bits (XC16's handles)");
_Static_assert(sizeof(port_context_t) == 6, "a context is three words: sp, splim, base");
