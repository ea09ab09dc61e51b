/*
 * test_sha256.c: SHA-256 against the FIPS 180-4 examples and the
 * coreutils sha256sum of a file.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/base/sha256.h"

static void digest(const char *text, size_t repeat, char hex[65])
{
    struct sha256 h;
    sha256_init(&h);
    for (size_t k = 0; k < repeat; k++)
        sha256_update(&h, text, strlen(text));
    sha256_hex(&h, hex);
}

static void test_known_digests(void **state)
{
    (void)state;
    char hex[65];
    digest("", 1, hex);
    assert_string_equal(hex, "e3b0c44298fc1c149afbf4c8996fb924"
                             "27ae41e4649b934ca495991b7852b855");
    digest("abc", 1, hex);
    assert_string_equal(hex, "ba7816bf8f01cfea414140de5dae2223"
                             "b00361a396177a9cb410ff61f20015ad");
    digest("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq", 1, hex);
    assert_string_equal(hex, "248d6a61d20638b8e5c026930c3e6039"
                             "a33ce45964ff2167f6ecedd419db06c1");
    digest("a", 1000000, hex);
    assert_string_equal(hex, "cdc76e5c9914fb9281a1c7e284d73e67"
                             "f1809a48a497200e046d39ccc7112cd0");
}

/* Long runs of blocks take the CPU's SHA extensions where it has them,
 * single blocks the plain code: the same digest however the bytes are
 * split (one update, then pieces of every size from 1 to 97 bytes). */
static void test_any_split_gives_one_digest(void **state)
{
    (void)state;
    size_t n = 200003;
    unsigned char *bytes = malloc(n);
    assert_non_null(bytes);
    uint32_t x = 12345;
    for (size_t i = 0; i < n; i++) {
        x = x * 1103515245u + 12345u;
        bytes[i] = (unsigned char)(x >> 16);
    }
    char whole[65], pieces[65];
    struct sha256 h;
    sha256_init(&h);
    sha256_update(&h, bytes, n);
    sha256_hex(&h, whole);
    sha256_init(&h);
    for (size_t at = 0, size = 1; at < n; size = size % 97 + 1) {
        size_t take = size < n - at ? size : n - at;
        sha256_update(&h, bytes + at, take);
        at += take;
    }
    sha256_hex(&h, pieces);
    assert_string_equal(whole, pieces);
    free(bytes);
}

static void test_file_matches_sha256sum(void **state)
{
    (void)state;
    char path[] = "/tmp/facet_test_sha_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    for (int k = 0; k < 100000; k++)
        fprintf(out, "v %d %d %d\n", k, k * 7 % 13, k % 5);
    fclose(out);
    char hex[65], command[256], expected[65] = "";
    struct facet_error err;
    assert_int_equal(sha256_file(path, hex, &err), FACET_OK);
    snprintf(command, sizeof command, "sha256sum %s", path);
    FILE *pipe = popen(command, "r");
    assert_non_null(pipe);
    assert_int_equal(fscanf(pipe, "%64s", expected), 1);
    pclose(pipe);
    assert_string_equal(hex, expected);
    unlink(path);
    assert_int_equal(sha256_file(path, hex, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, path));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_known_digests),
        cmocka_unit_test(test_any_split_gives_one_digest),
        cmocka_unit_test(test_file_matches_sha256sum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
