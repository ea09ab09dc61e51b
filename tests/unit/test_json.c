/*
 * test_json.c: the JSON writer places commas, escapes strings and never
 * writes NaN; every double it writes reads back (strtod) as the same
 * double, bit for bit, in the fewest of 15 to 17 digits.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/out/json.h"
#include "core/base/rng.h"

static void test_nested_document(void **state)
{
    (void)state;
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    struct json_writer w;
    json_init(&w, out);
    json_begin_object(&w);
    json_key(&w, "name");
    json_string(&w, "a \"quoted\"\\path\n\x01");
    json_key(&w, "list");
    json_begin_array(&w);
    json_integer(&w, 1);
    json_number(&w, 2.5);
    json_number(&w, NAN);
    json_bool(&w, 0);
    json_null(&w);
    json_begin_object(&w);
    json_end_object(&w);
    json_end_array(&w);
    json_key(&w, "empty");
    json_begin_array(&w);
    json_end_array(&w);
    json_end_object(&w);
    json_finish(&w);
    fclose(out);
    assert_string_equal(text,
        "{\"name\":\"a \\\"quoted\\\"\\\\path\\n\\u0001\","
        "\"list\":[1,2.5,null,false,null,{}],\"empty\":[]}\n");
    free(text);
}

/* Text from files need not be UTF-8: JSON gets '?' for a byte that is not,
 * keeps valid characters whole, and escapes every control character (C0,
 * DEL, C1), so the document is valid UTF-8 with no raw ESC or BEL. A
 * cut character (E2 82 C0) and a surrogate (ED A0 80) are '?' a byte. */
static void test_strings_are_clean_utf8(void **state)
{
    (void)state;
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    struct json_writer w;
    json_init(&w, out);
    json_string(&w, "a\x1b]0;t\x07\xff\xc3\xa9\x7f\xc2\x9b\xe2\x82\xac"
                    "\xe2\x82\xc0\xed\xa0\x80");
    fclose(out);
    assert_string_equal(text, "\"a\\u001b]0;t\\u0007?\xc3\xa9\\u007f"
                              "\\u009b\xe2\x82\xac???\?\?\?\"");
    free(text);
}

/* Writes one number as JSON and reads it back. */
static double round_trip(double value, char *text, size_t size)
{
    FILE *out = fmemopen(text, size, "w");
    struct json_writer w;
    json_init(&w, out);
    json_number(&w, value);
    fclose(out);
    return strtod(text, NULL);
}

static void test_numbers_read_back(void **state)
{
    (void)state;
    char text[64];
    /* The shortest form that reads back. */
    assert_true(round_trip(0.1, text, sizeof text) == 0.1);
    assert_string_equal(text, "0.1");
    assert_true(round_trip(1215639.0000000009, text, sizeof text) ==
                1215639.0000000009);
    assert_string_equal(text, "1215639.000000001");  /* 16 digits */
    assert_true(round_trip(0.1 + 0.2, text, sizeof text) == 0.1 + 0.2);
    assert_string_equal(text, "0.30000000000000004");  /* 17 */
    /* Random bit patterns over the whole range (subnormals included), and
     * values of a run's size moved by a few units in the last place. */
    struct rng rng;
    rng_seed(&rng, 17);
    for (int k = 0; k < 200000; k++) {
        double value;
        if (k % 2 == 0) {
            uint64_t bits = rng_next(&rng);
            memcpy(&value, &bits, sizeof value);
            if (!isfinite(value))
                continue;
        } else {
            value = nextafter(1e6 * rng_uniform(&rng), INFINITY);
        }
        double back = round_trip(value, text, sizeof text);
        assert_memory_equal(&back, &value, sizeof value);
        assert_true(strlen(text) <= 24);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nested_document),
        cmocka_unit_test(test_numbers_read_back),
        cmocka_unit_test(test_strings_are_clean_utf8),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
