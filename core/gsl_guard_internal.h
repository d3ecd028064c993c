/* The guard that keeps GSL from aborting or printing inside the library
 * (internal: not installed, not part of the public API).
 *
 * nl_gsl_enter() and nl_gsl_leave() bracket every library entry point whose
 * work can reach a GSL routine.  While at least one guarded call runs in the
 * process, GSL's error handler is the library's, which neither prints nor
 * aborts but records GSL's reason, file and line in a per-thread buffer; the
 * GSL routine then returns its status (or NAN for the special functions),
 * which the caller turns into an NL_E* code with nl_gsl_reason() in the
 * message.  The outermost enter of the process saves the caller's handler;
 * the last leave restores it.
 *
 * Calls nest and are counted: a thread-local depth makes nested brackets in
 * one thread a counter increment; the first bracket of a thread takes an
 * atomic fast path when another bracket already holds the handler, and a
 * mutex only to install or restore it.  OpenMP workers started inside a
 * bracket are covered by their parent's bracket (the handler is per
 * process); what GSL reports on a worker is recorded in that worker's
 * buffer. */
#ifndef NL_GSL_GUARD_H
#define NL_GSL_GUARD_H

/* Install the library's GSL handler (outermost bracket of the process) or
 * count one more bracket.  The outermost bracket of a thread clears that
 * thread's recorded reason.  Every enter is matched by one leave. */
void nl_gsl_enter(void);

/* End one bracket; the last one of the process puts back the handler that
 * was in place at the first enter. */
void nl_gsl_leave(void);

/* The reason GSL gave for its last error in this thread inside a bracket,
 * or, if it reported none, gsl_strerror(gsl_status).  Valid until the next
 * GSL error or outermost enter in this thread. */
const char *nl_gsl_reason(int gsl_status);

#endif
