/* The binary32 instance of the build check (src/core/cbx_ieee.c). */
#define CBX_FLOAT 1
#include "cbx_ieee.c"
