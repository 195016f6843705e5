/* out_csv.c - one line per organ: index, object, position, frame, sizes. */
#include "writer.h"

void
csv_write(struct sink *s, const struct result *r)
{
	sink_puts(s, "n,object,x,y,z,ux,uy,uz,vx,vy,vz,wx,wy,wz,"
	    "scale,radius\n");
	for (size_t i = 0; i < r->count; i++) {
		const struct organ *o = &r->organs[i];
		double v[3];
		const double *vals[4] = { o->pos, o->u, v, o->w };

		organ_v(o, v);
		sink_uint(s, i);
		sink_putc(s, ',');
		/* Object names are identifiers: no quoting needed. */
		sink_puts(s, r->objects[o->object]);
		for (int k = 0; k < 4; k++)
			for (int j = 0; j < 3; j++) {
				sink_putc(s, ',');
				sink_num(s, vals[k][j]);
			}
		sink_putc(s, ',');
		sink_num(s, o->scale);
		sink_putc(s, ',');
		sink_num(s, o->radius);
		sink_putc(s, '\n');
	}
}
