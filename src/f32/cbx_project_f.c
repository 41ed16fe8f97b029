/* The binary32 family of src/algo/cbx_project.c: the same source, instantiated for
 * float (src/core/cbx_prec.h; names end in f, e.g. cbx_project_boxf). */
#define CBX_FLOAT 1
#include "cbx_project.c"
