/* A firmware that jumps where there is no code: the simulator must say so
 * and fail, not hang. */
#include <stdint.h>

int main(void) {
    void (*nowhere)(void) = (void (*)(void))(uintptr_t)0x3FF0; /* past the program */
    nowhere();
    return 0;
}
