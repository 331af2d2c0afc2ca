/*
 * config.h - the points and limits of tests/weights.conf.
 */
#ifndef CONFIG_H
#define CONFIG_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "grader.h"

/* What a test may print (stdout and stderr) unless the file says otherwise
 * ("output KIB"): a line of debugging output per call is a few hundred KiB
 * at most.  The most a file may allow. */
#define CONFIG_OUTPUT_KIB 4096
#define CONFIG_OUTPUT_KIB_MAX 65536

typedef struct {
    bool parts[NPARTS];        /* the parts graded when none is named: the
                                  "parts" line (Parts 1-3b by default)    */
    double core[NPARTS];       /* points of each part's core tests      */
    double hard[NPARTS];       /* points of each part's hard-case tests */
    bool hard_is_bonus;        /* hard points on top of the total        */
    bool full_hints;           /* "hints full": a hard case's cause gives
                                  the challenge's answer; by default
                                  ("hints challenge") it points to the
                                  handout's challenge                     */
    double timeout;            /* seconds per test                       */
    double part_time;          /* seconds a part's runs may take in all   */
    long output_kib;           /* KiB a test may print before it is stopped */
    uint64_t seed;
} GradeConfig;

/* Reads path; 0, or -1 with "path:line: reason" in err. */
int config_read(GradeConfig *cfg, const char *path, char *err, size_t errlen);

#endif
