/*
 * The precision of this translation unit: binary32 when CBX_FLOAT is
 * defined before the first include (the *_f.c files), binary64 otherwise.
 * Opens that instance of include/cbx_prec_begin.h for the rest of the unit, so
 * the algorithm's sources (written once) read cbx_fp, CBX_K(...) and the
 * logic names in the unit's format.
 */
#ifndef CBX_PREC_H
#define CBX_PREC_H

#include "certbox.h"
#include "cbx_build.h"

#ifdef CBX_FLOAT
#define CBX_INST 32
#else
#define CBX_INST 64
#endif
#include "cbx_prec_begin.h"

#endif /* CBX_PREC_H */
