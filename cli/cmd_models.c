/* noiselab models: the model catalogue. */
#include "cli.h"
#include "opt.h"
#include "../core/model.h"

#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: noiselab models [--json]\n\n"
    "Lists every model a --acf or --spectrum SPEC may name, with its parameters\n"
    "and formula.  A spec is NAME[:key=value,...], e.g. markov:scale=8.\n"
    "In 2D and 3D every R model is isotropic, R(|lag|), unless given\n"
    "  sep          separable: R(x) R(y) R(z) / var^(dim-1)\n"
    "  angle=DEG    rotate the correlation ellipse about z: its major axis (where\n"
    "               scale applies) DEG degrees from +x towards +y\n"
    "  ratio=Q      length along the rotated y axis / length along x\n"
    "  zratio=Q     length along z / length along x\n"
    "(for %s after a final ';', e.g. \"expr:exp(-r);ratio=0.5\").\n"
    "A family's peer names (gstat's Sph, GSTools' Gaussian, RandomFields' RMexp)\n"
    "take the peer's own keys, e.g. Sph:psill=0.59,range=897; gstat's names take\n"
    "gstat's anis = c(angle, ratio): angle=P is the major axis P degrees clockwise\n"
    "from +y (north), as variogram --direction, so Sph:...,angle=P,ratio=S is\n"
    "spherical:...,angle=(90 - P),ratio=S (with ratio alone, angle=90).\n"
    "Lags are lengths (a grid's lag is its index times the spacing); frequencies\n"
    "in cycles per unit length; spectra are two-sided densities whose integral\n"
    "is the variance R(0).\n"
    "Structures join with + and * ('*' first, no parentheses), each with its own\n"
    "keys: \"spherical:var=0.59,scale=897,nugget=0.05 + markov:var=0.2,scale=300\"\n"
    "(R: the sum, or the product, of the structures'; an expr: structure last or\n"
    "ended by ';'; parameters of a sum named NAME.I, e.g. var.2; docs/models.md).\n";

/* A peer alias's keys as the catalogue writes them: "psill=1,range=A". */
static void peer_keys(const nl_family_alias *a, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = 0;
    for (size_t k = 0; k < a->nparams && len < size; k++) {
        const nl_family_param *p = &a->params[k];
        if (p->placeholder)
            len += (size_t)snprintf(buf + len, size - len, "%s%s=%s", k ? "," : "", p->name, p->placeholder);
        else
            len += (size_t)snprintf(buf + len, size - len, "%s%s=%g", k ? "," : "", p->name, p->def);
    }
}

static json_t *family_json(const nl_model_info *c, const nl_family *f)
{
    json_t *peers = json_array(), *aliases = json_array();
    char keys[256];
    for (const char *a = f->aliases; *a;) {
        size_t len = strcspn(a, " ");
        json_array_append_new(aliases, json_stringn(a, len));
        a += len;
        a += strspn(a, " ");
    }
    for (size_t k = 0; k < f->npeers; k++) {
        peer_keys(&f->peers[k], keys, sizeof keys);
        json_array_append_new(peers, json_pack("{s:s,s:s,s:s,s:s}", "name", f->peers[k].name, "peer",
                                               f->peers[k].peer, "params", keys, "formula", f->peers[k].formula));
    }
    return json_pack("{s:s,s:s,s:s,s:o,s:o}", "name", c->name, "params", c->params, "formula", c->formula,
                     "aliases", aliases, "peers", peers);
}

/* One family: its spec, formula, other names, and the peers' names with
 * their own keys. */
static void family_text(const nl_model_info *c, const nl_family *f)
{
    char keys[256];
    printf("%-14s %s\n%14s %s\n", c->name, c->params, "", c->formula);
    if (*f->aliases)
        printf("%14s also named: %s\n", "", f->aliases);
    for (size_t k = 0; k < f->npeers; k++) {
        peer_keys(&f->peers[k], keys, sizeof keys);
        printf("%14s %-12s %s:%s  R = %s\n", "", f->peers[k].peer, f->peers[k].name, keys, f->peers[k].formula);
    }
}

int cli_cmd_models(int argc, char **argv)
{
    static const cli_opt rows[] = {
    {.name = "json", .type = CLI_OPT_FLAG}, {0}};
    int json = 0;
    size_t n;
    const nl_model_info *cat = nl_model_catalogue(&n);
    if (cli_opt_parse("models", NULL, rows, &json, argc, argv)) {
        char list[256];
        nl_family_names(NL_FAMILY_ARGUMENT, 0, " and ", list, sizeof list);
        printf(help, list);
        return 0;
    }
    cli_no_operands("models", argc, argv);
    if (json) {
        json_t *arr = json_array();
        for (size_t i = 0; i < n; i++)
            json_array_append_new(arr, family_json(&cat[i], nl_family_get(i)));
        cli_json_print(json_pack("{s:o}", "models", arr));
        return 0;
    }
    for (size_t i = 0; i < n; i++)
        family_text(&cat[i], nl_family_get(i));
    return 0;
}
