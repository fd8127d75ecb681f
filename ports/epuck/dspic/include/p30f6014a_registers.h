/* The dsPIC30F6014A's special function registers the port and the e-puck
 * board use, at their addresses in the datasheet's SFR maps (DS70143:
 * core, interrupt controller, Timer1-5, I2C, UART1, 12-bit ADC, I/O ports),
 * with the bits used. Every SFR is a 16-bit word in near data space. */
#ifndef P30F6014A_REGISTERS_H
#define P30F6014A_REGISTERS_H

#include <stdint.h>

#define DSPIC_SFR(address) (*(volatile uint16_t *)(address))

/* ---- CPU core ---- */
#define SPLIM DSPIC_SFR(0x0020)
#define TBLPAG DSPIC_SFR(0x0032)
#define PSVPAG DSPIC_SFR(0x0034)
#define SR DSPIC_SFR(0x0042)
#define CORCON DSPIC_SFR(0x0044)
#define SR_IPL_MASK 0x00E0u /* CPU priority IPL<2:0>: 7 masks every interrupt */
#define CORCON_IPL3 0x0008u /* set while a trap runs (priority 8..15) */

/* ---- interrupt controller ---- */
#define INTCON1 DSPIC_SFR(0x0080)
#define IFS0 DSPIC_SFR(0x0084)
#define IFS1 DSPIC_SFR(0x0086)
#define IEC0 DSPIC_SFR(0x008C)
#define IEC1 DSPIC_SFR(0x008E)
#define IPC0 DSPIC_SFR(0x0094)
#define IPC1 DSPIC_SFR(0x0096)
#define IPC2 DSPIC_SFR(0x0098)
#define IPC5 DSPIC_SFR(0x009E)
#define INTCON1_STKERR 0x0004u
#define INTCON1_ADDRERR 0x0008u
#define INTCON1_MATHERR 0x0010u
/* Flags are cleared one bit at a time: XC16 makes `IFSx &= ~bit` one
 * BCLR, so a flag the hardware sets meanwhile is not written back lost.
 * IFS0/IEC0 bits: */
#define IRQ0_T1 0x0008u
#define IRQ0_T2 0x0040u
#define IRQ0_T3 0x0080u
#define IRQ0_ADC 0x0800u
/* IFS1/IEC1 bits */
#define IRQ1_T4 0x0020u
#define IRQ1_T5 0x0040u
/* Priority fields, 3 bits each: IPC0 T1 <14:12>; IPC1 T2 <10:8>, T3 <14:12>;
 * IPC2 ADC <14:12>; IPC5 T4 <6:4>, T5 <10:8>. */
#define IPC0_T1_SHIFT 12
#define IPC1_T2_SHIFT 8
#define IPC1_T3_SHIFT 12
#define IPC2_ADC_SHIFT 12
#define IPC5_T4_SHIFT 4
#define IPC5_T5_SHIFT 8
#define IPC_FIELD 0x7u

/* ---- timers: a 16-bit count, period PRx, control TxCON ---- */
#define TMR1 DSPIC_SFR(0x0100)
#define PR1 DSPIC_SFR(0x0102)
#define T1CON DSPIC_SFR(0x0104)
#define TMR2 DSPIC_SFR(0x0106)
#define PR2 DSPIC_SFR(0x010C)
#define TMR3 DSPIC_SFR(0x010A)
#define PR3 DSPIC_SFR(0x010E)
#define T2CON DSPIC_SFR(0x0110)
#define T3CON DSPIC_SFR(0x0112)
#define TMR4 DSPIC_SFR(0x0114)
#define TMR5 DSPIC_SFR(0x0118)
#define PR4 DSPIC_SFR(0x011A)
#define PR5 DSPIC_SFR(0x011C)
#define T4CON DSPIC_SFR(0x011E)
#define T5CON DSPIC_SFR(0x0120)
#define TCON_ON 0x8000u /* TON; TSIDL (bit 13) stays 0: timers run in Idle */
#define TCON_PRESCALE_1 0x0000u
#define TCON_PRESCALE_8 0x0010u
#define TCON_PRESCALE_256 0x0030u
#define TCON_EXTERNAL 0x0002u /* TCS: count rising edges on the TxCK pin (T4CK RC3, T5CK RC4) */

/* ---- I2C (SCL RG2, SDA RG3) ---- */
#define I2CRCV DSPIC_SFR(0x0200)
#define I2CTRN DSPIC_SFR(0x0202)
#define I2CBRG DSPIC_SFR(0x0204)
#define I2CCON DSPIC_SFR(0x0206)
#define I2CSTAT DSPIC_SFR(0x0208)
#define I2CCON_I2CEN 0x8000u
#define I2CCON_ACKDT 0x0020u /* 1: the master answers NACK */
#define I2CCON_ACKEN 0x0010u
#define I2CCON_RCEN 0x0008u
#define I2CCON_PEN 0x0004u  /* STOP */
#define I2CCON_RSEN 0x0002u /* repeated START */
#define I2CCON_SEN 0x0001u  /* START */
#define I2CSTAT_ACKSTAT 0x8000u /* 1: the slave did not acknowledge */
#define I2CSTAT_TRSTAT 0x4000u  /* a master transmission under way */
#define I2CSTAT_BCL 0x0400u     /* bus collision */
#define I2CSTAT_RBF 0x0002u     /* a received byte in I2CRCV */

/* ---- UART1 ---- */
#define U1MODE DSPIC_SFR(0x020C)
#define U1STA DSPIC_SFR(0x020E)
#define U1TXREG DSPIC_SFR(0x0210)
#define U1BRG DSPIC_SFR(0x0214)
#define UMODE_UARTEN 0x8000u /* PDSEL 00, STSEL 0: 8 data bits, no parity, 1 stop */
#define USTA_UTXEN 0x0400u
#define USTA_UTXBF 0x0200u /* transmit buffer full */
#define USTA_TRMT 0x0100u  /* transmit shift register empty */

/* ---- 12-bit ADC ---- */
#define ADCBUF0 DSPIC_SFR(0x0280)
#define ADCON1 DSPIC_SFR(0x02A0)
#define ADCON2 DSPIC_SFR(0x02A2)
#define ADCON3 DSPIC_SFR(0x02A4)
#define ADCHS DSPIC_SFR(0x02A6)
#define ADPCFG DSPIC_SFR(0x02A8)
#define ADCON1_ADON 0x8000u
#define ADCON1_SSRC_AUTO 0x00E0u /* conversion starts SAMC TAD after sampling does */
#define ADCON1_SAMP 0x0002u
#define ADCON3_SAMC(tad) ((uint16_t)((tad) << 8))
#define ADCON3_ADCS(n) ((uint16_t)(n)) /* TAD = TCY (n + 1) / 2 */

/* ---- I/O ports: TRIS 1 = input, LAT drives, PORT reads the pins ---- */
#define TRISA DSPIC_SFR(0x02C0)
#define LATA DSPIC_SFR(0x02C4)
#define TRISC DSPIC_SFR(0x02CC)
#define PORTC DSPIC_SFR(0x02CE)
#define LATC DSPIC_SFR(0x02D0)
#define TRISD DSPIC_SFR(0x02D2)
#define PORTD DSPIC_SFR(0x02D4)
#define LATD DSPIC_SFR(0x02D6)
#define TRISF DSPIC_SFR(0x02DE)
#define LATF DSPIC_SFR(0x02E2)
#define TRISG DSPIC_SFR(0x02E4)
#define PORTG DSPIC_SFR(0x02E6)
#define LATG DSPIC_SFR(0x02E8)

#endif
