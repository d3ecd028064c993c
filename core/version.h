/* The library's version: the one place it is written.  The Makefile reads
 * NL_VERSION_MAJOR/MINOR/PATCH from here (for the soname, noiselab.pc and
 * `noiselab --version`), so they cannot disagree.
 *
 * The soname changes with NL_VERSION_MAJOR: a program linked against
 * libnoiselab.so.1 runs with any 1.y.z. */
#ifndef NL_VERSION_H
#define NL_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

#define NL_VERSION_MAJOR 1
#define NL_VERSION_MINOR 0
#define NL_VERSION_PATCH 0

#define NL_VERSION_STR_(x) #x
#define NL_VERSION_XSTR_(x) NL_VERSION_STR_(x)
/* "MAJOR.MINOR.PATCH" of the headers compiled against, e.g. "0.1.0". */
#define NL_VERSION_STRING                                                                                      \
    NL_VERSION_XSTR_(NL_VERSION_MAJOR) "." NL_VERSION_XSTR_(NL_VERSION_MINOR) "." NL_VERSION_XSTR_(NL_VERSION_PATCH)

/* "MAJOR.MINOR.PATCH" of the library linked at run time (a static string;
 * compare with NL_VERSION_STRING to detect a header/library mismatch).
 * Thread-safe. */
const char *nl_version(void);

#ifdef __cplusplus
}
#endif

#endif
