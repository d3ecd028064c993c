/* The version of the library that is running (core/version.h). */
#include "version.h"

const char *nl_version(void)
{
    return NL_VERSION_STRING;
}
