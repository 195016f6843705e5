/*
 * progress.h - a long run's progress on the terminal: the primordia a
 * model has placed, then the bytes written.
 */
#ifndef PROGRESS_H
#define PROGRESS_H

#include "base/sink.h"

/* The run starts now: nothing shows before half a second of it. */
void	progress_start(void);
/* A model's count placed so far; last: it is done, rub the line out. */
void	progress_placed(long long done, int last);
/* A block written: used of about expected (struct job's told). */
void	progress_written(const struct budget *);
/* Rub the line out, if one shows. */
void	progress_clear(void);

#endif
