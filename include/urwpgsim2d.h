/*
 * urwpgsim2d.h - the C interface of the URWPGSim2D native library (liburwpgsim2d.so).
 *
 * A batch is N matches of one competition item. In each, one team plays the actions the caller
 * gives and the other team an opponent strategy ("idle", "chase-ball", or "demo", the item's demo
 * strategy). Match i started from seed s and given the same actions is the match
 * `run --item ITEM --seed s --cycles CYCLES` plays with the same decisions.
 *
 * Buffers belong to the caller; the library writes into them and keeps no pointer to them.
 * Every function returning int returns URW_OK (0) or an error code, and then urw_last_error()
 * describes the error in one line (UTF-8, valid until the next failing call on the same thread).
 * A batch is not thread-safe: one thread at a time steps it; different batches may run on
 * different threads.
 *
 * Observation of a match (observation_size floats): for every fish of the match, by index,
 * x/1000, y/1000 (metres), cos(heading), sin(heading), speed/1000; for every ball x/1000, y/1000,
 * vx/1000, vy/1000; then the time fraction min(cycle / cycles, 1). As the strategies see them
 * (the item's observation noise included).
 * Action of a match (action_size int32): a speed code and a turn code 0..15 per fish of the team.
 * Reward: the change of (own score - other team's score) during the step.
 * terminated: the match ended. truncated: `cycles` steps (or max_steps) were played and it plays on.
 * Next-step autoreset: the step after a match ended starts it again (seed: the next of its seed
 * sequence) and ignores its action; that step's reward is 0 and neither flag is set.
 */
#ifndef URWPGSIM2D_H
#define URWPGSIM2D_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define URW_OK 0
#define URW_BAD_ARGUMENT 1 /* an unknown item or opponent, a size out of range, a buffer of the wrong length, an action not 0..15 */
#define URW_BAD_HANDLE 2   /* a null handle */
#define URW_BAD_STATE 3    /* urw_batch_step before urw_batch_reset; a destroyed handle */
#define URW_FAILURE 4      /* anything else (a bug: please report it with the message) */

typedef struct urw_batch urw_batch;

/* The message of the last error on this thread ("" when none). */
const char *urw_last_error(void);

/* Creates a batch of `count` matches (1..65536) of `item` (e.g. "polo-1v1"), the actions playing
 * `team` (0, or 1 in an item of two teams), each match lasting `cycles` cycles (1 or more). */
int urw_batch_create(const char *item, const char *opponent, int32_t count, int32_t team, int32_t cycles, urw_batch **batch);

/* Frees a batch (NULL is ignored). */
void urw_batch_destroy(urw_batch *batch);

/* The batch's sizes; any pointer may be NULL. */
int urw_batch_sizes(urw_batch *batch, int32_t *count, int32_t *observation_size, int32_t *action_size, int32_t *team_fish);

/* Starts every match: match i from seeds[i] (seeds_length == count); episodes are truncated after
 * max_steps steps (0: at the match's cycles). Writes count * observation_size floats. */
int urw_batch_reset(urw_batch *batch, const uint64_t *seeds, int64_t seeds_length, int32_t max_steps,
                    float *observations, int64_t observations_length);

/* Plays one cycle of every match. actions: count * action_size; observations: count * observation_size;
 * rewards, terminated, truncated: `count` each (terminated and truncated: one byte per match, 0 or 1).
 * Nothing is played when an argument is refused. Allocates nothing (apart from restarting a match). */
int urw_batch_step(urw_batch *batch, const int32_t *actions, int64_t actions_length,
                   float *observations, int64_t observations_length,
                   float *rewards, uint8_t *terminated, uint8_t *truncated, int64_t count);

/* Each match's cycles played in its episode (count), score of team 0 and team 1 (2 * count), and
 * the seed of its episode (count; `run --seed` replays it). */
int urw_batch_info(urw_batch *batch, int32_t *cycles, int32_t *goals, uint64_t *seeds, int64_t count);

#ifdef __cplusplus
}
#endif

#endif
