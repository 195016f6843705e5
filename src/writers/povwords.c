/*
 * povwords.c - POV-Ray's reserved words, which a #declare cannot use.
 * The list is POV-Ray 3.8's (a superset of Debian's 3.7), as the
 * language documents it; all are lowercase, so any identifier with a
 * capital letter is free, as POV-Ray's own style advice says.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "writers/povwords.h"

/* Sorted, for bsearch(). */
static const char *const words[] = {
	"aa_level", "aa_threshold", "abs", "absorption", "accuracy", "acos",
	"acosh", "adaptive", "adc_bailout", "agate", "agate_turb",
	"aitoff_hammer", "akima_spline", "albedo", "albinos", "all",
	"all_intersections", "alpha", "altitude", "always_sample", "ambient",
	"ambient_light", "amount", "angle", "anisotropy", "aoi", "aperture",
	"append", "arc_angle", "area_illumination", "area_light", "array",
	"asc", "ascii", "asin", "asinh", "assumed_gamma", "atan", "atan2",
	"atanh", "autostop", "average", "b_spline", "background",
	"balthasart", "basic_x_spline", "behrmann", "bend", "bezier_spline",
	"bias", "bicubic_patch", "bitwise_and", "bitwise_or", "bitwise_xor",
	"black_hole", "blend_gamma", "blend_mode", "blob", "blue",
	"blur_samples", "bmp", "bokeh", "bounded_by", "bourke", "box",
	"boxed", "bozo", "break", "breakpoint", "brick", "brick_size",
	"brightness", "brilliance", "bt2020", "bt709", "bump_map",
	"bump_size", "bumps", "camera", "camera_direction", "camera_location",
	"camera_right", "camera_type", "camera_up", "case", "caustics",
	"ceil", "cells", "charset", "checker", "chr", "circular",
	"clipped_by", "clock", "clock_on", "collect", "color", "color_map",
	"colour", "colour_map", "component", "composite", "concat", "cone",
	"confidence", "conic_sweep", "conserve_energy", "contained_by",
	"continuity", "control0", "control1", "coords", "cos", "cosh",
	"count", "crackle", "crand", "cristal", "cube", "cubic",
	"cubic_spline", "cubic_wave", "cubicle", "cutaway_textures",
	"cylinder", "cylindrical", "datetime", "debug", "declare", "default",
	"defined", "degrees", "density", "density_file", "density_map",
	"dents", "deprecated", "df3", "dictionary", "difference", "diffuse",
	"dimension_size", "dimensions", "direction", "disc", "dispersion",
	"dispersion_samples", "displace", "dist_exp", "distance",
	"distance_maximum", "div", "double_illuminate", "dtag",
	"eccentricity", "eckert_iv", "eckert_vi", "edwards", "else", "elseif",
	"emission", "end", "error", "error_bound", "evaluate", "exp",
	"expand_thresholds", "exponent", "exr", "extended_x_spline",
	"exterior", "extinction", "face_indices", "facets", "fade_color",
	"fade_colour", "fade_distance", "fade_power", "falloff",
	"falloff_angle", "false", "fclose", "file_exists", "filter", "finish",
	"fisheye", "fisheye_equisolid_angle", "fisheye_orthographic",
	"fisheye_stereographic", "fixed", "flatness", "flip", "floor",
	"focal_point", "fog", "fog_alt", "fog_offset", "fog_type", "fopen",
	"for", "form", "freedom_degree", "frequency", "fresnel", "function",
	"gall", "gamma", "gather", "general_x_spline", "get_normal",
	"get_normal_count", "get_normal_indices", "get_triangle_count",
	"get_uv", "get_uv_count", "get_uv_indices", "get_vertex",
	"get_vertex_count", "get_vertex_indices", "gif", "global",
	"global_lights", "global_settings", "gradient", "granite", "gray",
	"gray_threshold", "green", "grey", "grey_threshold", "grid",
	"gts_load", "gts_save", "hdr", "height_field", "heller", "hexagon",
	"hf_gray_16", "hf_grey_16", "hierarchy", "hobo_dyer", "hollow",
	"hypercomplex", "icosa", "if", "ifdef", "iff", "ifndef", "image_map",
	"image_pattern", "importance", "inbound", "include", "inner",
	"inside", "inside_point", "inside_vector", "int", "interior",
	"interior_texture", "internal", "interpolate", "intersection",
	"intervals", "inverse", "ior", "irid", "irid_wavelength",
	"is_smooth_triangle", "isosurface", "jitter", "jpeg", "julia",
	"julia_fractal", "keep", "lambda", "lambert_azimuthal",
	"lambert_cylindrical", "lathe", "lemon", "leopard", "light_group",
	"light_source", "linear_spline", "linear_sweep", "ln", "load_file",
	"local", "location", "log", "look_at", "looks_like",
	"low_error_factor", "macro", "magnet", "major_radius", "mandel",
	"map_type", "marble", "material", "material_map", "matrix", "max",
	"max_extent", "max_gradient", "max_intersections", "max_iteration",
	"max_sample", "max_trace", "max_trace_level", "maximal",
	"maximum_reuse", "media", "media_attenuation", "media_interaction",
	"mercator", "merge", "mesh", "mesh2", "mesh_camera", "metallic",
	"method", "metric", "miller_cylindrical", "min", "min_extent",
	"minimal", "minimum_reuse", "mixed", "mm_per_unit", "mod",
	"modulation", "mollweide", "mortar", "move", "natural_spline",
	"nearest_count", "no", "no_bump_scale", "no_image", "no_radiosity",
	"no_reflection", "no_shadow", "noise_generator", "normal",
	"normal_indices", "normal_map", "normal_vectors", "now",
	"number_of_sides", "number_of_tiles", "number_of_waves", "nurbs",
	"obj", "object", "octa", "octaves", "off", "offset", "omega",
	"omni_directional_stereo", "omnimax", "on", "once", "onion", "open",
	"optional", "orient", "orientation", "origin", "original",
	"orthographic", "outbound", "outside", "ovus", "panoramic",
	"parallaxe", "parallel", "parametric", "pass_through", "pattern",
	"pavement", "perspective", "peters", "pgm", "phase", "phong",
	"phong_size", "photons", "pi", "pigment", "pigment_map",
	"pigment_pattern", "planar", "plane", "planet", "plate_carree", "png",
	"point_at", "polarity", "poly", "poly_wave", "polygon", "polyline",
	"polynomial", "pot", "potential", "pow", "ppm", "precision",
	"precompute", "prefix", "premultiplied", "pretrace_end",
	"pretrace_start", "prism", "prod", "projected_through", "pwr",
	"quadratic_spline", "quadric", "quartic", "quaternion", "quick_color",
	"quick_colour", "quilted", "radial", "radians", "radiosity", "radius",
	"rainbow", "ramp_wave", "rand", "range", "ratio",
	"rational_bezier_patch", "read", "reciprocal", "recursion_limit",
	"red", "reflection", "reflection_exponent", "refraction", "render",
	"repeat", "rgb", "rgbf", "rgbft", "rgbt", "right", "ripples", "roll",
	"rotate", "roughness", "samples", "save_file", "sblue", "scale",
	"scallop_wave", "scattering", "screw", "seed", "select", "sgreen",
	"shadowless", "sin", "sine_wave", "sinh", "sint16be", "sint16le",
	"sint32be", "sint32le", "sint8", "size", "sky", "sky_sphere", "slice",
	"slope", "slope_map", "smooth", "smooth_triangle", "smyth_craster",
	"solid", "sor", "sor_spline", "spacing", "specular", "sphere",
	"sphere_sweep", "spherical", "spiral1", "spiral2", "spline",
	"split_union", "spotlight", "spotted", "sqr", "sqrt", "square",
	"sred", "srgb", "srgbf", "srgbft", "srgbt", "statistics", "stereo",
	"stl_load", "stl_save", "str", "strcmp", "strength", "strlen",
	"strlwr", "strupr", "sturm", "substr", "subsurface", "suffix", "sum",
	"superellipsoid", "switch", "sys", "t", "tan", "tanh", "target",
	"tau", "tcb_spline", "tension", "tessel", "tesselate", "tetra",
	"text", "texture", "texture_list", "texture_map", "tga", "thickness",
	"threshold", "tiff", "tightness", "tile2", "tiles", "tiling",
	"tolerance", "toroidal", "torus", "trace", "trace_uv", "transform",
	"translate", "translucency", "transmit", "triangle", "triangle_wave",
	"triangular", "true", "ttf", "turb_depth", "turbulence", "type", "u",
	"u_steps", "uint16be", "uint16le", "uint8", "ultra_wide_angle",
	"undef", "union", "unofficial", "up", "use_alpha", "use_color",
	"use_colour", "use_index", "user_defined", "utf8", "uv_indices",
	"uv_mapping", "uv_max", "uv_min", "uv_normal", "uv_reference",
	"uv_vectors", "uv_vertex", "v", "v_steps", "val", "van_der_grinten",
	"variance", "vaxis_rotate", "vcross", "vdot", "version",
	"vertex_vectors", "vlength", "vnormalize", "vrotate", "vstr",
	"vturbulence", "warning", "warp", "water_level", "waves", "while",
	"width", "with", "wood", "wrinkles", "write", "x", "xyz", "y", "yes",
	"z",
};

static int
cmp(const void *key, const void *elem)
{
	return strcmp(key, *(const char *const *)elem);
}

int
pov_reserved(const char *id)
{
	for (const char *p = id; *p != '\0'; p++)
		if (isupper((unsigned char)*p))
			return 0;
	return bsearch(id, words, sizeof(words) / sizeof(words[0]),
	    sizeof(words[0]), cmp) != NULL;
}
