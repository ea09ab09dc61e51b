/*
 * test_json.c: the JSON writer places commas, escapes strings and never
 * writes NaN.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/json.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nested_document),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
