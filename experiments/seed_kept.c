/* Experiment helper: count the seed samples kept exactly in a refined field.
 * usage: seed_kept SEED.exr FIELD.exr STEP -> "K of N" */
#include "../core/io.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    nl_field *s, *f;
    size_t step, kept = 0;
    if (argc != 4 || nl_field_read(argv[1], &s, NULL) || nl_field_read(argv[2], &f, NULL))
        return 2;
    step = strtoul(argv[3], NULL, 10);
    for (size_t j = 0; j < s->n[1]; j++)
        for (size_t i = 0; i < s->n[0]; i++)
            kept += f->data[j * step * f->n[0] + i * step] == s->data[j * s->n[0] + i];
    printf("%zu of %zu\n", kept, s->count);
    return 0;
}
