/* The report page's figure of a failing case (tests/grader/figures.c and
 * fig_*.c), drawn from the submission's answer: any numbers at all, NaN,
 * infinities and 1e308 among them.  The first two bytes pick one of the
 * public tests, the third its case; the rest are the answers' doubles, as
 * many as a case has outputs (for an image test, every pixel's, repeated). */
#include "fuzz.h"
#include "fuzz_public.h"
#include "../grader/figures.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const TestList *list = fuzz_public_tests();
    if (size < 3 + sizeof(double) || list->n == 0)
        return 0;
    const Test *t = &list->tests[(data[0] | data[1] << 8) % list->n];
    int c = data[2] % t->ncases, nout = kind_nout(t->kind);
    size_t nd = (size - 3) / sizeof(double);
    TestResult r;
    memset(&r, 0, sizeof r);
    r.ran = true;
    r.answers.got = calloc((size_t)t->ncases, sizeof *r.answers.got);
    r.answers.ok = calloc((size_t)t->ncases, sizeof *r.answers.ok);
    if (!r.answers.got || !r.answers.ok)
        abort();
    for (int k = 0; k < t->ncases; k++)
        for (int i = 0; i < nout; i++)
            memcpy(&r.answers.got[k][i], data + 3 + ((size_t)(k * nout + i) % nd) * sizeof(double),
                   sizeof(double));
    r.answers.answered = t->ncases;
    r.answers.first_bad = c;
    r.answers.failed = 1;
    Markup m;
    mk_init(&m);
    figure_case(&m, t, &r, c, r.answers.got[c]);
    mk_free(&m);
    answers_free(&r.answers);
    return 0;
}
