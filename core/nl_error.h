/* Status codes and the last error message of the library.
 *
 * Library code (core/, synth/, analysis/) never prints and never exits.  A
 * function that fails returns one of the NL_E* codes below and leaves a
 * one-line message, naming the bad value and what was expected, that the
 * caller reads with nl_errmsg().  The message is per thread. */
#ifndef NL_ERROR_H
#define NL_ERROR_H

enum {
    NL_OK = 0,
    NL_EINVAL = 1,   /* bad argument or option value (user input) */
    NL_EINPUT = 2,   /* malformed or unreadable input file */
    NL_ETOOBIG = 3,  /* size overflows or exceeds available memory */
    NL_ENOTPD = 4,   /* model is not positive definite where it must be */
    NL_EIO = 5,      /* writing an output failed */
    NL_ENOMEM = 6,   /* allocation failed although the size was accepted */
    NL_EFAIL = 7     /* numerical or library failure while running */
};

/* Record a message for status code `code` and return the code.
 * Use through NL_ERROR so that file and line are recorded too. */
int nl_error_set(int code, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#define NL_ERROR(code, ...) nl_error_set((code), __FILE__, __LINE__, __VA_ARGS__)

/* The last message recorded in this thread ("" if none). */
const char *nl_errmsg(void);

/* "file:line" where the last error was raised, for debugging. */
const char *nl_errwhere(void);

/* Is `code` caused by the user's input (exit status 2) rather than a
 * failure while running (exit status 1)? */
int nl_error_is_input(int code);

#endif
