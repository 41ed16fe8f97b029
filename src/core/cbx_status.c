/* Status names, for messages and logs. */
#include "certbox.h"
#include "cbx_build.h"

/*@ assigns \nothing;
    ensures \valid_read(\result); */
const char *cbx_status_name(cbx_status s)
{
    switch (s) {
    case CBX_OK: return "CBX_OK";
    case CBX_EMPTY: return "CBX_EMPTY";
    case CBX_EINVAL: return "CBX_EINVAL";
    case CBX_ERANGE: return "CBX_ERANGE";
    case CBX_EBEHIND: return "CBX_EBEHIND";
    default: return "CBX_UNKNOWN";
    }
}
