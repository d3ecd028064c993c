/* Provenance (core/provenance.h): format then parse gives the record back
 * bit for bit, the text is what the writers have always recorded, and a
 * damaged or hostile value is refused with one line naming its key. */
#include "../core/nl_error.h"
#include "../core/provenance.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

static nl_provenance sample_record(void)
{
    nl_provenance p;
    nl_provenance_init(&p);
    strcpy(p.model, "matern:scale=2.385,nu=1.5");
    strcpy(p.method, "subdiv:neighborhood=2,levels=7");
    strcpy(p.flags, "clamped");
    strcpy(p.version, "0.2.0");
    p.seed = UINT64_MAX, p.has_seed = 1;
    p.dim = 3, p.n[0] = 17, p.n[1] = 2, p.n[2] = 1;
    p.nspacing = 3, p.h[0] = 0.1, p.h[1] = 1.0 / 3, p.h[2] = 2.385e-7;
    p.norigin = 2, p.origin[0] = -5, p.origin[1] = 12;
    return p;
}

Test(provenance, round_trip_is_exact)
{
    nl_provenance p = sample_record(), q;
    nl_meta kv;
    cr_assert_eq(nl_provenance_format(&p, &kv), NL_OK);
    cr_expect_str_eq(kv.seed, "18446744073709551615");
    cr_expect_str_eq(kv.size, "17x2x1");
    cr_expect_str_eq(kv.spacing, "0.10000000000000001,0.33333333333333331,2.3850000000000002e-07");
    cr_expect_str_eq(kv.origin, "-5,12");
    cr_assert_eq(nl_provenance_parse(&kv, NL_PROV_ALL, &q), NL_OK, "%s", nl_errmsg());
    /* %.17g reads back to the same double: the records are equal as bytes */
    cr_expect_eq(memcmp(&p, &q, sizeof p), 0);
}

Test(provenance, keys_not_recorded_stay_empty)
{
    nl_provenance p, q;
    nl_meta kv;
    nl_provenance_init(&p);
    p.dim = 1, p.n[0] = 64;
    cr_assert_eq(nl_provenance_format(&p, &kv), NL_OK);
    for (int i = 0; i < NL_META_NKEYS; i++)
        cr_expect(strcmp(nl_meta_key(i), "size") ? !*nl_meta_value(&kv, i) : !strcmp(nl_meta_value(&kv, i), "64"));
    cr_assert_eq(nl_provenance_parse(&kv, NL_PROV_ALL, &q), NL_OK);
    cr_expect_eq(q.dim, 1);
    cr_expect_eq(q.n[1], 1);
    cr_expect_eq(q.has_seed + q.nspacing + q.norigin, 0);
    cr_expect_null(nl_meta_key(NL_META_NKEYS));
    cr_expect_null(nl_meta_value(&kv, -1));
}

/* Only the keys asked for are read: a bad origin does not stop a reader
 * that does not use it. */
Test(provenance, parse_reads_the_keys_selected)
{
    nl_meta kv = {0};
    nl_provenance q;
    strcpy(kv.seed, "42");
    strcpy(kv.origin, "not a number");
    cr_assert_eq(nl_provenance_parse(&kv, NL_PROV_SEED, &q), NL_OK);
    cr_expect(q.has_seed && q.seed == 42);
    cr_expect_eq(q.norigin, 0);
    cr_expect_eq(nl_provenance_parse(&kv, NL_PROV_ALL, &q), NL_EINPUT);
    cr_expect_eq(q.has_seed, 0); /* emptied on failure */
}

static void refused(const char *key, const char *value, const char *expect)
{
    nl_meta kv = {0};
    nl_provenance q;
    for (int i = 0; i < NL_META_NKEYS; i++)
        if (!strcmp(nl_meta_key(i), key))
            snprintf(nl_meta_slot(&kv, i), nl_meta_capacity(i), "%s", value);
    int st = nl_provenance_parse(&kv, NL_PROV_ALL, &q);
    cr_expect_neq(st, NL_OK, "%s \"%s\" accepted", key, value);
    cr_expect(nl_error_is_input(st), "%s \"%s\": status %d", key, value, st);
    cr_expect(strstr(nl_errmsg(), expect), "%s \"%s\": %s", key, value, nl_errmsg());
    if (strcmp(key, "seed")) /* the seed's message is synth --from's, as given */
        cr_expect_null(strchr(nl_errmsg(), '\n'), "%s: %s", key, nl_errmsg());
}

Test(provenance, bad_values_are_refused_with_one_line)
{
    refused("seed", "-1", "noiselab.seed: expected an integer from 0 to 2^64-1, got \"-1\"");
    refused("seed", "18446744073709551616", "noiselab.seed");
    refused("seed", " 5", "noiselab.seed");
    refused("size", "0", "noiselab.size: expected N, NxM or NxMxK");
    refused("size", "4x4x4x4", "noiselab.size");
    refused("size", "64x", "noiselab.size");
    refused("size", "x64", "noiselab.size");
    refused("size", "-3", "noiselab.size");
    refused("size", "99999999999999999999999", "noiselab.size");
    refused("spacing", "nan", "noiselab.spacing");
    refused("spacing", "1,inf", "noiselab.spacing");
    refused("spacing", "0", "noiselab.spacing");
    refused("spacing", "1,2,3,4", "noiselab.spacing");
    refused("spacing", "1,\n2", "noiselab.spacing: expected 1 to 3 positive finite numbers separated by commas, "
            "got \"1,?2\"");
    refused("origin", "1,2,3,4", "noiselab.origin");
    refused("origin", " 1", "noiselab.origin");
    refused("origin", "99999999999999999999999", "noiselab.origin");
    refused("origin", "nan", "noiselab.origin");
    refused("origin", "2.5,inf", "noiselab.origin");
    refused("model", "junk:x=1", "unknown model");
    refused("method", "fft\x01", "noiselab.method: expected text without control characters");
    refused("flags", "a\nb", "noiselab.flags");
}

/* A record filled to its last byte (a reader's bug, or memcpy) is refused,
 * not read past. */
Test(provenance, unterminated_value_is_refused)
{
    nl_meta kv = {0};
    nl_provenance q;
    memset(kv.method, 'a', sizeof kv.method);
    cr_expect_eq(nl_provenance_parse(&kv, NL_PROV_METHOD, &q), NL_EINPUT);
    cr_expect(strstr(nl_errmsg(), "noiselab.method: expected at most 255 bytes"), "%s", nl_errmsg());
}

Test(provenance, format_refuses_a_bad_record)
{
    nl_provenance p = sample_record();
    nl_meta kv;
    p.h[1] = -1;
    cr_expect_eq(nl_provenance_format(&p, &kv), NL_EINVAL);
    cr_expect_eq(kv.seed[0], 0); /* nothing half written */
    p = sample_record(), p.dim = 4;
    cr_expect_eq(nl_provenance_format(&p, &kv), NL_EINVAL);
    p = sample_record(), p.n[1] = 0;
    cr_expect_eq(nl_provenance_format(&p, &kv), NL_EINVAL);
    p = sample_record(), memset(p.version, 'v', sizeof p.version);
    cr_expect_eq(nl_provenance_format(&p, &kv), NL_EINVAL);
}

/* A record is data: a model naming a file is checked for its family and
 * text, and the file is not opened (a missing one is no error here; synth
 * --from reads it only when the command line names it). */
Test(provenance, image_model_is_not_opened)
{
    nl_meta kv = {0};
    nl_provenance q;
    snprintf(kv.model, sizeof kv.model, "image:/nonexistent/exemplar.exr");
    cr_assert_eq(nl_provenance_parse(&kv, NL_PROV_MODEL, &q), NL_OK, "%s", nl_errmsg());
    cr_expect_str_eq(q.model, "image:/nonexistent/exemplar.exr");
    snprintf(kv.model, sizeof kv.model, "image:a\nb");
    cr_expect_eq(nl_provenance_parse(&kv, NL_PROV_MODEL, &q), NL_EINPUT);
}
