/* json.h - JSON strings and numbers, for --settings and --gltf. */
#ifndef JSON_H
#define JSON_H

#include "base/sink.h"

/*
 * s as a JSON string: quotes, backslashes and control characters
 * escaped, UTF-8 kept, and bytes that are not UTF-8 made U+FFFD, so
 * that any scene text gives valid JSON.
 */
void	json_string(struct sink *, const char *s);
/* A finite number, as few digits as read back the same; else null. */
void	json_number(struct sink *, double);

#endif
