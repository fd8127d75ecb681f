; The camera's row interrupt (Timer4, counting HREF on T4CK = RC3): reads
; one row's pixels from RD8..RD15 by counting cycles, then calls
; board_camera_row_end (C) for the frame's bookkeeping. XC16 assembler,
; run through the C preprocessor (.S). NEVER ASSEMBLED NOR RUN: XC16 is
; not in Debian (../README.md, "The camera").
;
; Timing. The sensor's master clock is the dsPIC's 14.7456 MHz and, at the
; speed po3030k_setup.c sets for each subsampling mode, it puts out one
; byte every 8 clock cycles: one byte per 8 instruction cycles here, in a
; fixed phase (both from one oscillator). The loop below takes a byte in
; an 8-cycle slot and a pixel (2 bytes) in 16; delay_repeat NOPs pass the
; pixels skipped in between (16 cycles each). HREF rises one output pixel
; (16 cycles) before the first wanted pixel (the window's lead): the
; interrupt's latency (about 5 cycles, plus up to 2 for Timer4's clock
; synchronisation) and the 12 cycles of prologue put the first sample at
; about cycle 17-21 after HREF, inside the wanted pixel's first byte slot
; (16-23). That is arithmetic, not a measurement: it assumes nothing
; delays the interrupt, and the kernel's critical sections (CPU priority
; 7) do. A row read late is shifted and not detected (README).
;
; W0 byte, W1 destination, W2 pixels left, W3 delay NOPs - 1, W4 spare.

; Assembled only in a build with the camera (board.h, EPUCK_DSPIC_CAMERA).
#if defined(EPUCK_DSPIC_CAMERA) && EPUCK_DSPIC_CAMERA

        .equ    IFS1_ADDR, 0x0086
        .equ    T4IF_BIT, 5
        .equ    TMR4_ADDR, 0x0114
        .equ    PORTD_ADDR, 0x02D4

        .section .text
        .global __T4Interrupt
__T4Interrupt:
        push.d  w0                      ; 2  W0, W1
        push.d  w2                      ; 2  W2, W3
        push    RCOUNT                  ; 1  the interrupted code may be in a REPEAT
        bclr    IFS1_ADDR, #T4IF_BIT    ; 1
        clr     TMR4_ADDR               ; 1  the next row is href_per_row HREFs away
        mov     _camera_row_destination, w1 ; 1
        cp0     w1                      ; 1
        bra     z, done                 ; 1  (not taken)
        mov     _camera_row_columns, w2 ; 1
        mov     _camera_row_delay, w3   ; 1  (12 cycles to here)
pixel:
        mov     PORTD_ADDR, w0          ; 1  high byte: RD8..RD15
        lsr     w0, #8, w0              ; 1
        mov.b   w0, [w1++]              ; 1
        nop                             ; 5  to the next byte slot
        nop
        nop
        nop
        nop
        mov     PORTD_ADDR, w0          ; 1  low byte, 8 cycles after the high one
        lsr     w0, #8, w0              ; 1
        mov.b   w0, [w1++]              ; 1
        repeat  w3                      ; 1
        nop                             ; w3 + 1: the skipped pixels
        dec     w2, w2                  ; 1
        bra     nz, pixel               ; 2  taken: 16 + w3 cycles a pixel
        push.d  w4                      ; C may use W0-W7
        push.d  w6
        call    _board_camera_row_end
        pop.d   w6
        pop.d   w4
done:
        pop     RCOUNT
        pop.d   w2
        pop.d   w0
        retfie

#endif
        .end
