/* No kernel at all: what the C runtime and vector table cost alone. */
int main(void) {
    for (;;) {
    }
}
