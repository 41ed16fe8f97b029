/* The binary32 family of src/cbx_interval.c: the same source, instantiated for
 * float (src/cbx_prec.h; names end in f, e.g. cbx_transform_boxf). */
#define CBX_FLOAT 1
#include "cbx_interval.c"
