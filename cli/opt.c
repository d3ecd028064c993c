/* Option tables: getopt_long's table from the rows, and each value checked
 * and stored as it comes (cli/opt.h). */
#include "opt.h"
#include "cli.h"

#include <getopt.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

const char *const cli_bins_choices[] = {"gstat", "floor", NULL};

/* The most rows a command's table holds, groups opened. */
#define MAX_ROWS 64

/* The rows of a table with groups opened, each with its struct's offset. */
typedef struct {
    const cli_opt *row[MAX_ROWS];
    size_t base[MAX_ROWS];
    int n;
} flat_rows;

static void flatten(flat_rows *f, const cli_opt *rows, size_t base)
{
    for (; rows->type != CLI_OPT_END; rows++) {
        if (rows->type == CLI_OPT_GROUP) {
            flatten(f, rows->sub, base + rows->off);
            continue;
        }
        if (f->n == MAX_ROWS)
            cli_die(1, "option table over %d rows", MAX_ROWS);
        f->row[f->n] = rows, f->base[f->n++] = base;
    }
}

static void *field(void *obj, size_t base, size_t off) { return (char *)obj + base + off; }

/* "a, b or c" from the choices. */
static void choice_words(const char *const *c, char *buf, size_t len)
{
    size_t k = 0;
    buf[0] = 0;
    for (int i = 0; c[i] && k < len; i++)
        k += (size_t)snprintf(buf + k, len - k, "%s%s", i == 0 ? "" : c[i + 1] ? ", " : " or ", c[i]);
}

static int pick(const cli_opt *r, const char *label, const char *arg)
{
    char words[256];
    for (int i = 0; r->choices[i]; i++)
        if (strcmp(arg, r->choices[i]) == 0)
            return r->vals ? r->vals[i] : i;
    if (!r->what)
        choice_words(r->choices, words, sizeof words);
    cli_die(2, "%s: expected %s, got \"%s\"", label, r->what ? r->what : words, arg);
}

static void range_or_die(const cli_opt *r, unsigned flags, const char *label, double v, const char *arg)
{
    if (((flags & CLI_RANGE_LO) && !(v >= r->lo)) || ((flags & CLI_RANGE_HI) && !(v <= r->hi)))
        cli_die(2, "%s: expected %s, got \"%s\"", label, r->what, arg);
}

static const char *label_of(const cli_opt *r, char *buf, size_t len)
{
    if (r->label)
        return r->label;
    snprintf(buf, len, "--%s", r->name);
    return buf;
}

/* Check the value of row r and store it in obj (its rows' struct at base). */
static void take(const cli_opt *r, void *obj, size_t base, const char *label, const char *arg)
{
    void *p = field(obj, base, r->off);
    if (r->given)
        *(int *)field(obj, base, r->given - 1) = 1;
    if (!arg && r->type != CLI_OPT_FLAG && r->type != CLI_OPT_CALL) {
        if (r->type == CLI_OPT_DOUBLE || r->type == CLI_OPT_POSITIVE)
            *(double *)p = 0; /* an optional value left out */
        return;
    }
    switch (r->type) {
    case CLI_OPT_FLAG: *(int *)p = 1; break;
    case CLI_OPT_STRING: *(const char **)p = arg; break;
    case CLI_OPT_DOUBLE:
        *(double *)p = cli_parse_double(label, arg);
        range_or_die(r, r->flags, label, *(double *)p, arg);
        break;
    case CLI_OPT_POSITIVE: *(double *)p = cli_parse_positive(label, arg, r->what); break;
    case CLI_OPT_COUNT:
    case CLI_OPT_INT: {
        size_t v = (r->flags & CLI_AUTO) && strcmp(arg, "auto") == 0 ? 0 : cli_parse_count(label, arg, (size_t)r->lo);
        range_or_die(r, r->hi > 0 ? CLI_RANGE_HI : 0, label, (double)v, arg);
        if (r->type == CLI_OPT_INT)
            *(int *)p = (int)v;
        else
            *(size_t *)p = v;
        break;
    }
    case CLI_OPT_U64: *(uint64_t *)p = cli_parse_u64(label, arg); break;
    case CLI_OPT_CHOICE: *(int *)p = pick(r, label, arg); break;
    case CLI_OPT_SIZE: {
        int dim = cli_parse_size(label, arg, (size_t *)p, (size_t)r->lo);
        if (r->aux)
            *(int *)field(obj, base, r->aux - 1) = dim;
        break;
    }
    case CLI_OPT_DIM: *(int *)p = cli_parse_dim(arg, (int)r->hi); break;
    case CLI_OPT_PAIR: cli_parse_pair(label, arg, (double *)p, (double *)p + 1); break;
    case CLI_OPT_CALL: r->fn((char *)obj + base, label, arg); break;
    default: break;
    }
}

/* getopt_long's table (the rows' index + 256 as codes, then --help) and
 * the short options. */
static void build(const flat_rows *f, struct option *lo, char *so)
{
    int k = 0;
    strcpy(so, ":h");
    for (int i = 0; i < f->n; i++) {
        const cli_opt *r = f->row[i];
        int has = r->type == CLI_OPT_FLAG ? no_argument : r->flags & CLI_OPTIONAL ? optional_argument
                                                                                     : required_argument;
        lo[k++] = (struct option){r->name, has, 0, 256 + i};
        if (r->letter) {
            size_t l = strlen(so);
            so[l] = r->letter, so[l + 1] = has == no_argument ? 0 : ':', so[l + 2] = 0;
        }
    }
    lo[k++] = (struct option){"help", no_argument, 0, 'h'};
    lo[k] = (struct option){0};
}

/* The first row that fills the field row i fills (or calls its function on
 * the same struct): the option it is one of. */
static int slot_of(const flat_rows *f, int i)
{
    const cli_opt *r = f->row[i];
    for (int j = 0; j < i; j++) {
        const cli_opt *q = f->row[j];
        if (f->base[j] == f->base[i] && (r->type == CLI_OPT_CALL ? q->type == CLI_OPT_CALL && q->fn == r->fn
                                                                 : q->type != CLI_OPT_CALL && q->off == r->off))
            return j;
    }
    return i;
}

/* Row i given with value arg: exit 2 when its option was given before
 * (row seen[slot] - 1, with value first[slot]) and may not be repeated. */
static void once(const char *cmd, const flat_rows *f, int i, const char *arg, int *seen, const char **first)
{
    char l1[64], l2[64];
    int s = slot_of(f, i), j = seen[s] - 1;
    const char *now = label_of(f->row[i], l1, sizeof l1);
    if (j >= 0 && !(f->row[i]->flags & CLI_REPEAT)) {
        const char *before = label_of(f->row[j], l2, sizeof l2);
        if (j == i && (!arg || !first[s]))
            cli_die(2, "%s: %s: given twice; expected it once", cmd, now);
        if (j == i)
            cli_die(2, "%s: %s: given twice (\"%s\", then \"%s\"); expected it once", cmd, now, first[s], arg);
        cli_die(2, "%s: %s%s%s%s: %s was given too; expected one of %s and %s", cmd, now, arg ? " \"" : "",
                arg ? arg : "", arg ? "\"" : "", before, before, now);
    }
    seen[s] = i + 1, first[s] = arg;
}

int cli_opt_parse(const char *cmd, const char *help, const cli_opt *rows, void *obj, int argc, char **argv)
{
    flat_rows f = {.n = 0};
    struct option lo[MAX_ROWS + 2];
    char so[3 * MAX_ROWS + 3], label[64];
    int c, seen[MAX_ROWS] = {0};
    const char *first[MAX_ROWS] = {0};
    flatten(&f, rows, 0);
    build(&f, lo, so);
    while ((c = cli_getopt(argc, argv, so, lo, cmd)) != -1) {
        int i = c - 256;
        if (c == 'h') {
            if (help)
                fputs(help, stdout);
            return 1;
        }
        if (c < 256) /* a short option: its row */
            for (i = 0; f.row[i]->letter != c; i++)
                ;
        once(cmd, &f, i, optarg, seen, first);
        take(f.row[i], obj, f.base[i], label_of(f.row[i], label, sizeof label), optarg);
    }
    return 0;
}

void cli_opt_need(const char *cmd, const cli_opt *rows, const void *obj)
{
    flat_rows f = {.n = 0};
    char label[64];
    flatten(&f, rows, 0);
    for (int i = 0; i < f.n; i++) {
        const cli_opt *r = f.row[i];
        const char *p = (const char *)obj + f.base[i] + r->off;
        int set = r->type == CLI_OPT_STRING  ? *(const char *const *)p != NULL
                  : r->type == CLI_OPT_COUNT ? *(const size_t *)p != 0
                                             : *(const int *)p != 0;
        if (r->need && !set)
            cli_die(2, "%s: %s: expected %s", cmd, label_of(r, label, sizeof label), r->need);
    }
}
