/* The registry of synthesis methods: the one list (synth/method.h). */
#include "method_internal.h"

#include <stdio.h>
#include <string.h>

/* Every method, in the order help and messages list them: X(name) for the
 * descriptor nl_method_<name> of synth/method_<name>.c, one line each. */
#define METHODS(X) \
    X(fft)         \
    X(subdiv)      \
    X(midpoint)    \
    X(circulant)   \
    X(cholesky)    \
    X(faulting)    \
    X(sparse)      \
    X(lattice)     \
    X(intrinsic)

#define DECLARE(name) extern const nl_method_type nl_method_##name;
#define ENTRY(name) &nl_method_##name,
METHODS(DECLARE)
static const nl_method_type *const methods[] = {METHODS(ENTRY)};

/* Names reserved for methods to come. */
static const char *const planned[] = {"rank1"};

#define COUNT(a) ((int)(sizeof(a) / sizeof *(a)))

int nl_method_count(void) { return COUNT(methods); }

const nl_method_type *nl_method_at(int i) { return i >= 0 && i < COUNT(methods) ? methods[i] : NULL; }

const nl_method_type *nl_method_find(const char *name)
{
    for (int i = 0; name && i < COUNT(methods); i++)
        if (!strcmp(methods[i]->name, name))
            return methods[i];
    return NULL;
}

const nl_method_type *nl_method_ranked(int i)
{
    for (int pass = 0, k = 0; pass < 2; pass++)
        for (int j = 0; j < COUNT(methods); j++)
            if ((!(methods[j]->caps & NL_METHOD_EXACT)) == pass && k++ == i)
                return methods[j];
    return NULL;
}

int nl_method_planned(const char *name)
{
    for (int i = 0; name && i < COUNT(planned); i++)
        if (!strcmp(planned[i], name))
            return 1;
    return 0;
}

static int listed(const nl_method_type *t, unsigned caps, const char *opt)
{
    caps &= ~NL_METHOD_EXACT_FIRST;
    return (t->caps & caps) == caps && (!opt || nl_method_option_index(t, opt) >= 0);
}

int nl_method_names(unsigned caps, const char *opt, const char *sep, const char *last, char *buf, size_t size)
{
    int total = 0, k = 0;
    size_t len = 0;
    for (int i = 0; i < COUNT(methods); i++)
        total += listed(methods[i], caps, opt);
    if (size)
        buf[0] = 0;
    for (int i = 0; i < COUNT(methods) && size; i++) {
        const nl_method_type *t = caps & NL_METHOD_EXACT_FIRST ? nl_method_ranked(i) : methods[i];
        if (!listed(t, caps, opt))
            continue;
        int w = snprintf(buf + len, size - len, "%s%s", k == 0 ? "" : k + 1 == total ? last : sep, t->name);
        k++;
        if (w < 0 || (size_t)w >= size - len)
            break;
        len += (size_t)w;
    }
    return total;
}
