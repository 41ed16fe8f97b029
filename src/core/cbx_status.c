/* Status names, for messages and logs. */
#include "certbox.h"
#include "cbx_build.h"

/*@ assigns \nothing;
    ensures \valid_read(\result); */
const char *cbx_status_name(cbx_status s)
{
    const char *n = "CBX_UNKNOWN";
    switch (s) {
    case CBX_OK: n = "CBX_OK"; break;
    case CBX_EMPTY: n = "CBX_EMPTY"; break;
    case CBX_EINVAL: n = "CBX_EINVAL"; break;
    case CBX_ERANGE: n = "CBX_ERANGE"; break;
    case CBX_EBEHIND: n = "CBX_EBEHIND"; break;
    default: break;
    }
    return n;
}
