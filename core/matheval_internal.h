/* The one door to libmatheval: every expression a user gives (expr:,
 * spectrum:, nonlin's expr: g, sparse's kernel and angle) is checked here
 * before libmatheval's scanner sees it.  That scanner echoes any character
 * it has no rule for to stdout and drops it (flex's default rule), so an
 * expression like "exp(-t)?" would be accepted as "exp(-t)" with a stray
 * "?" on stdout. */
#ifndef NL_MATHEVAL_INTERNAL_H
#define NL_MATHEVAL_INTERNAL_H

#include <stddef.h>

/* The characters an expression may hold: letters, digits, _ . + - * / ^
 * ( ) space and tab.  (libmatheval's documented syntax; its scanner also
 * takes '[' inside names and newline as an end, neither of which any of our
 * expressions uses.) */
#define NL_MATHEVAL_CHARS "letters, digits and _ . + - * / ^ ( ) and spaces"

/* Index of the first character of `text` outside NL_MATHEVAL_CHARS, or
 * strlen(text) when there is none. */
size_t nl_matheval_bad_char(const char *text);

/* Compile `text` with evaluator_create into *out.  NL_EINVAL, with a message
 * starting "WHAT: ", for a character outside NL_MATHEVAL_CHARS (named, with
 * its 1-based position) or an expression libmatheval refuses; *out is then
 * NULL.  Nothing is written to stdout either way. */
int nl_matheval_create(const char *what, const char *text, void **out);

#endif
