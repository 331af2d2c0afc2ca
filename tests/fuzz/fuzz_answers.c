/* The answers a test's child sends back (tests/grader/check.c): written by
 * the harness, but the student's code shares its process and may write
 * anything there.  The first two bytes pick one of the public tests; the
 * rest is split as a batch of that test run twice (batch_split), and each
 * piece judged, or, when it does not split so, judged whole. */
#include "fuzz.h"
#include "fuzz_public.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const TestList *list = fuzz_public_tests();
    if (size < 2 || list->n == 0)
        return 0;
    const Test *t = &list->tests[(data[0] | data[1] << 8) % list->n];
    char *answers = fuzz_text(data + 2, size - 2);
    const char *from[2] = { answers, NULL };
    size_t len[2] = { size - 2, 0 };
    int pieces = batch_split(answers, size - 2, 2, from, len) == 2 ? 2 : 1;
    if (pieces == 1)
        from[0] = answers, len[0] = size - 2;
    for (int k = 0; k < pieces; k++) {
        char *out = NULL;
        Answers a;
        check_answers(t, from[k], len[k], &out, &a);
        answers_free(&a);
        free(out);
    }
    free(answers);
    return 0;
}
