/* signalsim decider plugin ABI (docs/decider.md "The C ABI"): what a shared library implements to be
 * signalsim's turn-signal decider (`--decider lib:PATH.so`) or traffic-light judge
 * (`--light-judge lib:PATH.so`). Plain C: a plugin may be written in C, C++, Rust or anything with
 * a C FFI. signalsim loads it with dlopen and checks signalsim_plugin_abi_version() first.
 *
 * Lifetime: create once per run (after the ego departed), step once per simulation step, destroy
 * once. Every pointer signalsim passes is valid during the call only; strings are UTF-8 and
 * NUL-terminated. A plugin keeps its state behind the opaque handle create returns: signalsim may run
 * several plugins (and several instances of one) in one process, never concurrently on one handle.
 *
 * Units: metres, seconds, radians, m/s, m/s^2. Positions `s` are along the ego's route (the route
 * coordinate of docs/behaviour.md §T2); x/y are SUMO net coordinates.
 *
 * Version history: 1 (signalsim 0.1): first version.
 */
#ifndef SIGNALSIM_DECIDER_PLUGIN_H
#define SIGNALSIM_DECIDER_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SIGNALSIM_PLUGIN_ABI_VERSION 1u

/* ---- values ------------------------------------------------------------------------------------ */

/* The blinker: what a decider answers. */
typedef enum { SS_BLINKER_NONE = 0, SS_BLINKER_LEFT = 1, SS_BLINKER_RIGHT = 2, SS_BLINKER_HAZARD = 3 } ss_blinker;

/* Autoware's lanelet turn_direction (docs/behaviour.md §T1.3); NONE: the attribute is absent. */
typedef enum { SS_TURN_NONE = 0, SS_TURN_STRAIGHT = 1, SS_TURN_LEFT = 2, SS_TURN_RIGHT = 3 } ss_turn_direction;

/* A lanelet's role in a roundabout (docs/behaviour.md §T5). */
typedef enum { SS_ROUNDABOUT_NONE = 0, SS_ROUNDABOUT_ENTRY = 1, SS_ROUNDABOUT_INTERNAL = 2, SS_ROUNDABOUT_EXIT = 3 } ss_roundabout_role;

/* Autoware's TurnIndicatorsCommand / HazardLightsCommand values (docs/behaviour.md §T1.1). */
typedef enum { SS_INDICATOR_NO_COMMAND = 0, SS_INDICATOR_DISABLE = 1, SS_INDICATOR_LEFT = 2, SS_INDICATOR_RIGHT = 3 } ss_turn_indicator;
typedef enum { SS_HAZARD_NO_COMMAND = 0, SS_HAZARD_DISABLE = 1, SS_HAZARD_ENABLE = 2 } ss_hazard;

/* Which behaviour module a request comes from. */
typedef enum {
  SS_MODULE_NONE = 0, SS_MODULE_LANE_CHANGE = 1, SS_MODULE_AVOIDANCE = 2, SS_MODULE_PULL_OUT = 3, SS_MODULE_PULL_OVER = 4
} ss_module;

/* A traffic-light judge's answer for one light. */
typedef enum { SS_LIGHT_GO = 0, SS_LIGHT_STOP = 1 } ss_light_decision;

typedef struct { double x, y; } ss_point;

/* A name and its value as text (the run's parameters, a lanelet's tags). */
typedef struct { const char* key; const char* value; } ss_key_value;

/* One lanelet of the route (a SUMO lane, normal or internal, placed on s). */
typedef struct {
  const char* id;                  /* SUMO lane id (":J_0_0" for an internal lane) */
  const char* edge_id;
  const char* junction_id;         /* the junction an internal lane lies in; "" for normal lanes */
  double s_start, s_end;           /* [m] route positions of the lane's start and end */
  double length;                   /* [m] SUMO lane length (= s_end - s_start) */
  double speed_limit;              /* [m/s] */
  ss_turn_direction turn_direction;
  ss_roundabout_role roundabout_role;
  const char* roundabout_id;       /* "" when not in a roundabout */
  double turn_signal_distance;     /* [m] the lanelet's turn_signal_distance; NaN when it has none */
  const ss_key_value* tags;        /* lane params (exit_turn_signal_left, enable_exit_turn_signal, ...) */
  size_t tag_count;
  const ss_point* centerline;      /* net coordinates, in driving direction */
  size_t centerline_size;
  /* The turn directions of every map successor of the lane, on or off the route (Autoware's
   * "near next turn lane" check, docs/behaviour.md §T4.1); in the net's connection order. */
  const ss_turn_direction* successor_turn_directions;
  size_t successor_turn_direction_count;
  int leaves_ring_at_end;          /* 1: a ring lane whose end has a connection off the ring (an exit branches there) */
} ss_lanelet;

/* One lateral motion the behaviour modules plan on the route (docs/maneuvers.md). */
typedef struct {
  ss_module module;
  const char* edge_id;             /* the edge it is driven on */
  double s_start, s_end;           /* [m] base_link route s where the lateral motion starts and ends */
  double shift;                    /* [m] lateral, left positive */
} ss_shift_line;

/* The whole route and the run's settings, given once to create. */
typedef struct {
  const char* scenario;            /* the scenario's name */
  double step_length;              /* [s] */
  double vehicle_length;           /* [m] */
  double base_link_to_front;       /* [m] */
  const ss_key_value* parameters;  /* every parameter of the run by signalsim's name (docs/parameters.md), sorted */
  size_t parameter_count;
  const ss_lanelet* lanelets;      /* the route in driving order; contiguous in s */
  size_t lanelet_count;
  const ss_shift_line* shift_lines;/* the planned maneuvers, in route order */
  size_t shift_line_count;
} ss_run;

/* The ego at the step's start. */
typedef struct {
  double x, y, yaw;                /* [m] front bumper in net coordinates; [rad] heading, 0 = east, counter-clockwise */
  double speed, accel;             /* [m/s] signed (negative while backing up); [m/s^2] */
  double s_front, s_base;          /* [m] route positions of the front bumper and of base_link */
} ss_ego;

/* One behaviour request (docs/behaviour.md §T1.2): desired and required sections on s. */
typedef struct {
  ss_module module;                /* SS_MODULE_NONE: no request this step (the rest is 0) */
  ss_turn_indicator turn;
  ss_hazard hazard;
  double desired_start, desired_end, required_start, required_end;  /* [m] route s */
} ss_request;

/* One signal element as perception delivered it (docs/lights.md). */
typedef struct {
  const char* color;               /* "red", "amber", "green", "white", "unknown" */
  const char* shape;               /* "circle", "left_arrow", "right_arrow", "up_arrow", ... */
  const char* status;              /* "solid_on", "solid_off", "flashing", "unknown" */
  double confidence;               /* [0, 1] */
} ss_signal_element;

/* One light ahead within the judge's window. */
typedef struct {
  const char* tls_id;
  int link_index;                  /* the ego's link in the light's state string */
  size_t lanelet_index;            /* the approach lanelet (index into ss_run.lanelets) */
  double stop_line_s;              /* [m] route s of the stop line */
  double distance;                 /* [m] front bumper to the stop line (> 0 ahead) */
  int delivered;                   /* 1: a message arrived this step (one without this light has no elements); 0: none (keep the last) */
  const ss_signal_element* elements; /* the delivered elements (none: nothing recognised) */
  size_t element_count;
  double time_to_red;              /* [s] V2I's predicted time to red of the ego's link; NaN without V2I */
} ss_light;

/* What a step gives a plugin. */
typedef struct {
  double time;                     /* [s] simulation time of the step's observation */
  ss_ego ego;
  size_t window_first, window_last;/* lanelets [first, last) of ss_run.lanelets within the decider's window */
  ss_request request;              /* the behaviour modules' merged request this step */
  const ss_light* lights;          /* the lights ahead within the judge's window, nearest first */
  size_t light_count;
} ss_step;

/* What a light judge answers for one light (the same order as ss_step.lights). */
typedef struct {
  ss_light_decision decision;
  char reason[64];                 /* optional, NUL-terminated; kept in the timeline's events */
} ss_light_answer;

/* ---- the functions a plugin exports ---------------------------------------------------------- */

/* Declared with default visibility: a plugin built with -fvisibility=hidden still exports them. */
#if defined(__GNUC__)
#define SIGNALSIM_PLUGIN_EXPORT __attribute__((visibility("default")))
#else
#define SIGNALSIM_PLUGIN_EXPORT
#endif

/* Required: the ABI the plugin was built against (return SIGNALSIM_PLUGIN_ABI_VERSION). */
SIGNALSIM_PLUGIN_EXPORT uint32_t signalsim_plugin_abi_version(void);

/* Optional: the plugin's name and version, printed in summaries ("my_decider 1.2"). */
SIGNALSIM_PLUGIN_EXPORT const char* signalsim_plugin_name(void);

/* The decider role (all three, or none). create returns NULL on failure and writes a reason into
 * `error` (at most error_size bytes, NUL-terminated). step returns 0 and writes `blinker`, or
 * returns non-zero and writes a reason into `error`: the run ends as an error. */
SIGNALSIM_PLUGIN_EXPORT void* signalsim_decider_create(const ss_run* run, char* error, size_t error_size);
SIGNALSIM_PLUGIN_EXPORT int signalsim_decider_step(void* decider, const ss_step* step, ss_blinker* blinker, char* error, size_t error_size);
SIGNALSIM_PLUGIN_EXPORT void signalsim_decider_destroy(void* decider);

/* The light-judge role (all three, or none): one answer per light of step->lights. */
SIGNALSIM_PLUGIN_EXPORT void* signalsim_light_judge_create(const ss_run* run, char* error, size_t error_size);
SIGNALSIM_PLUGIN_EXPORT int signalsim_light_judge_step(void* judge, const ss_step* step, ss_light_answer* answers, char* error, size_t error_size);
SIGNALSIM_PLUGIN_EXPORT void signalsim_light_judge_destroy(void* judge);

#ifdef __cplusplus
}
#endif

#endif /* SIGNALSIM_DECIDER_PLUGIN_H */
