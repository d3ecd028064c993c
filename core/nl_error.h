/* Status codes and the last error message of the library.
 *
 * Library code (core/, synth/, analysis/, render/) never prints, exits or
 * aborts.  A function that fails returns one of the NL_E* codes below and
 * leaves a one-line message, naming the bad value and what was expected, that
 * the caller reads with nl_errmsg().  The message is per thread (thread-local
 * storage): nl_errmsg() and nl_errwhere() are thread-safe and report the last
 * error of the calling thread.
 *
 * GSL.  GSL's default error handler prints and aborts.  The library does not
 * rely on the caller turning it off: every library function whose work can
 * reach a GSL routine brackets that work with an internal guard
 * (core/gsl_guard_internal.h).  While at least one such call is running anywhere in
 * the process, GSL's error handler of the process is the library's, which
 * neither prints nor aborts but records GSL's reason; the GSL routine then
 * returns its status, which the library turns into an NL_E* code whose
 * message includes GSL's reason (a failed Cholesky is NL_ENOTPD, a failed
 * eigen- or least-squares solve NL_EFAIL), or, for functions that return a
 * value (nl_model_acf, nl_model_spectrum_iso, nl_dist_quantile), NAN.  The
 * handler installed before the first of those calls (whatever the caller set,
 * or GSL's default) is restored when the last one returns.  Consequences for
 * a program that also uses GSL directly: a thread of its own calling GSL
 * while another thread is inside the library sees the library's handler
 * (its GSL errors then return a status instead of reaching its handler), and
 * a handler it sets during a library call is replaced by the saved one when
 * that call returns.  The guard allocates nothing and is thread-safe. */
#ifndef NL_ERROR_H
#define NL_ERROR_H

#ifdef __cplusplus
extern "C" {
#endif

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

/* The longest message kept, in bytes with its terminating NUL. */
#define NL_ERRMSG_MAX 4096

/* Record a message for status code `code` and return the code.
 * Use through NL_ERROR so that file and line are recorded too.  A message
 * longer than NL_ERRMSG_MAX - 1 bytes keeps its first 1024 bytes and its
 * end, joined by " [... N bytes left out ...] " (N its whole length), so
 * that the reason after a long model spec survives.  Thread-safe
 * (per-thread buffer). */
int nl_error_set(int code, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#define NL_ERROR(code, ...) nl_error_set((code), __FILE__, __LINE__, __VA_ARGS__)

/* The last message recorded in this thread ("" if none); valid until the
 * next error in this thread.  Successful calls do not clear it. */
const char *nl_errmsg(void);

/* "file:line" where the last error was raised, for debugging. */
const char *nl_errwhere(void);

/* Is `code` caused by the user's input (exit status 2) rather than a
 * failure while running (exit status 1)? */
int nl_error_is_input(int code);

#ifdef __cplusplus
}
#endif

#endif
