/* The slab splits shared by the slab tests (tests/test_slabs*.c). */
#ifndef NL_TEST_SLABS_H
#define NL_TEST_SLABS_H

#include "../core/field.h"

#include <stddef.h>

/* Fill f (the field's dim and size but n[dim - 1], the slab's rows) with
 * the rows s0 .. of the field; an NL_* status. */
typedef int slab_fn(const void *ctx, size_t s0, nl_field *f);

/* Every split of check_slab_splits (tests/test_slabs.c): block splits for
 * 1, 2, 3, 4, 9 and 12 ranks, uneven cuts, single rows; each slab from fn
 * equal to full's rows bit for bit (the test fails naming `what`). */
void check_slab_splits(const nl_field *full, slab_fn *fn, const void *ctx, const char *what);

/* Empty slabs skipped so far in this process. */
size_t slab_zero_rows_seen(void);

#endif
