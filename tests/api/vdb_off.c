/* The descriptor core/formats/vdb.c makes in a build without OpenVDB,
 * compiled and run by tests/test_vdb.c: prints "NAME EXT SUMMARY" and
 * exits 0 when the format is off with neither reader nor writer. */
#include "../../core/format.h"

#include <stdio.h>

extern const nl_format nl_format_vdb;

int main(void)
{
    const nl_format *t = &nl_format_vdb;
    printf("%s %s %s\n", t->name, t->extensions, t->summary);
    return (t->flags & NL_FORMAT_OFF) && !t->read && !t->write && !t->read_stream ? 0 : 1;
}
