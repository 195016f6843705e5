/* cover.c - stub */
#include "cover.h"

void cover_init(struct cover *cv, const struct curve *c, double r0, long long n) { (void)c; (void)r0; (void)n; cv->on = 0; }
void cover_free(struct cover *cv) { (void)cv; }
void cover_add(struct cover *cv, const struct curve *c, double t, double x, double y, double r) { (void)cv; (void)c; (void)t; (void)x; (void)y; (void)r; }
int cover_skip(struct cover *cv, const struct curve *c, double *t, double x, double y, double r) { (void)cv; (void)c; (void)t; (void)x; (void)y; (void)r; return 0; }
