/* The family registry: the list of core/families/list.h, look-ups, and
 * the lists of names that messages print. */
#include "family.h"
#include "model_internal.h"

#include <pthread.h>
#include <stdio.h>
#include <string.h>

#define NL_FAMILY(id) extern const nl_family nl_family_##id;
#include "families/list.h"
#undef NL_FAMILY

static const nl_family *const registry[] = {
#define NL_FAMILY(id) &nl_family_##id,
#include "families/list.h"
#undef NL_FAMILY
};

size_t nl_family_count(void) { return sizeof registry / sizeof *registry; }

const nl_family *nl_family_get(size_t i) { return i < nl_family_count() ? registry[i] : NULL; }

int nl_model_word_in(const char *list, const char *w, size_t len)
{
    const char *p = list;
    while (p && *p) {
        size_t l = strcspn(p, " ");
        if (l == len && strncmp(p, w, len) == 0)
            return 1;
        p += l;
        p += strspn(p, " ");
    }
    return 0;
}

const nl_family *nl_family_find(const char *name, size_t len)
{
    for (size_t i = 0; i < nl_family_count(); i++)
        if (strlen(registry[i]->name) == len && strncmp(name, registry[i]->name, len) == 0)
            return registry[i];
    for (size_t i = 0; i < nl_family_count(); i++)
        if (nl_model_word_in(registry[i]->aliases, name, len))
            return registry[i];
    return NULL;
}

const nl_family_alias *nl_family_find_peer(const char *name, size_t len, const nl_family **fam)
{
    for (size_t i = 0; i < nl_family_count(); i++)
        for (size_t k = 0; k < registry[i]->npeers; k++)
            if (strlen(registry[i]->peers[k].name) == len && strncmp(name, registry[i]->peers[k].name, len) == 0) {
                *fam = registry[i];
                return &registry[i]->peers[k];
            }
    return NULL;
}

int nl_family_param_index(const nl_family *f, const char *name)
{
    for (size_t k = 0; k < f->nparams; k++)
        if (strcmp(f->params[k].name, name) == 0)
            return (int)k;
    return -1;
}

int nl_family_role_index(const nl_family *f, nl_param_role role)
{
    for (size_t k = 0; k < f->nparams; k++)
        if (f->params[k].role == role)
            return (int)k;
    return -1;
}

size_t nl_family_names(unsigned with, unsigned without, const char *last, char *buf, size_t size)
{
    size_t n = 0, count = 0, len = 0;
    for (size_t i = 0; i < nl_family_count(); i++)
        count += (registry[i]->flags & with) == with && !(registry[i]->flags & without);
    if (size)
        buf[0] = 0;
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = registry[i];
        const char *sep = n == 0 ? "" : n + 1 == count ? last : ", ";
        int w;
        if ((f->flags & with) != with || (f->flags & without))
            continue;
        w = snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, "%s%s%s", sep, f->name,
                     f->flags & NL_FAMILY_ARGUMENT ? ":" : "");
        len += w > 0 ? (size_t)w : 0;
        n++;
    }
    return len;
}

const nl_family *nl_model_family(const nl_model *m) { return m->fam; }

/* The catalogue of core/model.h, made once from the registry. */
#define CAT_TEXT 160
static nl_model_info catalogue[sizeof registry / sizeof *registry];
static char cat_name[sizeof registry / sizeof *registry][CAT_TEXT];
static char cat_params[sizeof registry / sizeof *registry][CAT_TEXT];
static pthread_once_t cat_once = PTHREAD_ONCE_INIT;

/* One parameter as the catalogue writes it: "alpha=A", "scale=1". */
static size_t param_text(const nl_family_param *p, char *buf, size_t size)
{
    int n;
    if (p->placeholder)
        n = snprintf(buf, size, "%s=%s", p->name, p->placeholder);
    else if (p->def_text)
        n = snprintf(buf, size, "%s=%s", p->name, p->def_text);
    else
        n = snprintf(buf, size, "%s=%g", p->name, p->def);
    return n > 0 ? (size_t)n : 0;
}

/* "alpha=A [,scale=1,var=1,nugget=0]": the required parameters, then the
 * optional ones in brackets; an argument family's usage, then its keys
 * after ';'. */
static void params_text(const nl_family *f, char *buf, size_t size)
{
    size_t len = 0, nreq = 0, nopt = 0;
    int arg = (f->flags & NL_FAMILY_ARGUMENT) != 0;
    buf[0] = 0;
    if (arg)
        len = (size_t)snprintf(buf, size, "%s", f->usage);
    for (size_t k = 0; k < f->nparams && len < size; k++)
        if (f->params[k].placeholder) {
            len += (size_t)snprintf(buf + len, size - len, "%s", nreq++ ? "," : "");
            if (len < size)
                len += param_text(&f->params[k], buf + len, size - len);
        }
    for (size_t k = 0; k < f->nparams && len < size; k++)
        if (!f->params[k].placeholder) {
            const char *open = arg ? " [;" : nreq ? " [," : "[";
            len += (size_t)snprintf(buf + len, size - len, "%s", nopt++ ? "," : open);
            if (len < size)
                len += param_text(&f->params[k], buf + len, size - len);
        }
    if (nopt && len < size)
        snprintf(buf + len, size - len, "]");
}

static void make_catalogue(void)
{
    for (size_t i = 0; i < nl_family_count(); i++) {
        const nl_family *f = registry[i];
        if (f->flags & NL_FAMILY_ARGUMENT)
            snprintf(cat_name[i], CAT_TEXT, "%s:%s", f->name, f->argument);
        else
            snprintf(cat_name[i], CAT_TEXT, "%s", f->name);
        params_text(f, cat_params[i], CAT_TEXT);
        catalogue[i].name = cat_name[i];
        catalogue[i].params = cat_params[i];
        catalogue[i].formula = f->formula;
    }
}

const nl_model_info *nl_model_catalogue(size_t *count)
{
    pthread_once(&cat_once, make_catalogue);
    *count = nl_family_count();
    return catalogue;
}
