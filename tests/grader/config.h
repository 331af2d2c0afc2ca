/*
 * config.h - the points and limits of tests/weights.conf.
 */
#ifndef CONFIG_H
#define CONFIG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "grader.h"

typedef struct {
    bool parts[NPARTS];        /* the parts graded when none is named: the
                                  "parts" line (Parts 1-3b by default)    */
    double core[NPARTS];       /* points of each part's core tests      */
    double hard[NPARTS];       /* points of each part's hard-case tests */
    bool hard_is_bonus;        /* hard points on top of the total        */
    double timeout;            /* seconds per test                       */
    uint64_t seed;
} GradeConfig;

/* Reads path; 0, or -1 with "path:line: reason" in err. */
int config_read(GradeConfig *cfg, const char *path, char *err, size_t errlen);

#endif
