/*
 * Box2D's side of the thread-CPU crowd comparison (benchmarks/box2d.sh): the crowd scene the
 * project exports (`scene N FILE` of the side-by-side harness: the bodies of `run --crowd N`, in mm)
 * stepped in a Box2D v3 world, each b2World_Step timed by the thread's CPU clock.
 *
 *   crowd_cpu SCENE WARM MEASURE   ->   "b2crowd N CPU_MS WALL_MS" (medians over MEASURE steps after WARM)
 *
 * The world: no gravity, one worker, sleeping off, one 100 ms step of 4 sub-steps a cycle. Fish are
 * two capsules (head and body 190 x 45 mm, tail 278 x 28 mm), driven before each step at their
 * speed along their heading and their turn rate (the crowd's fixed decisions); balls are circles
 * slowed before each step by the project's water drag; obstacles, goal blocks and the pool's four
 * walls are static.
 */
#define _POSIX_C_SOURCE 199309L
#include "box2d/box2d.h"
#include "box2d/collision.h"
#include "box2d/math_functions.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct {
	b2BodyId id;
	float speed; /* m/s along the heading */
	float turn;  /* rad/s */
} Swimmer;

typedef struct {
	Swimmer* items;
	int count, capacity;
} Swimmers;

typedef struct {
	b2BodyId* items;
	int count, capacity;
} Bodies;

static void* grow(void* items, int* capacity, size_t size)
{
	*capacity = *capacity ? 2 * *capacity : 256;
	void* more = realloc(items, (size_t)*capacity * size);
	if (!more) {
		fprintf(stderr, "crowd_cpu: out of memory\n");
		exit(1);
	}
	return more;
}

static double seconds_of(clockid_t clock)
{
	struct timespec t;
	clock_gettime(clock, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void* a, const void* b)
{
	double x = *(const double*)a, y = *(const double*)b;
	return (x > y) - (x < y);
}

static double median_of(double* v, int n)
{
	qsort(v, (size_t)n, sizeof *v, by_value);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The project's water drag on a ball (mm/s^2 at a speed in mm/s), here in m/s^2 at m/s. */
static float drag(float speed)
{
	if (speed >= 0.1f) return 0.25f;
	if (speed >= 0.05f) return 0.1f;
	if (speed >= 0.025f) return 0.025f;
	return 0.00625f;
}

static b2BodyId fixed_body(b2WorldId world, b2Vec2 at, float angle)
{
	b2BodyDef def = b2DefaultBodyDef();
	def.type = b2_staticBody;
	def.position = at;
	def.rotation = b2MakeRot(angle);
	return b2CreateBody(world, &def);
}

int main(int argc, char** argv)
{
	if (argc != 4 || atoi(argv[3]) < 1 || atoi(argv[2]) < 0) {
		fprintf(stderr, "usage: crowd_cpu SCENE WARM MEASURE (MEASURE at least 1)\n");
		return 2;
	}
	int warm = atoi(argv[2]), measure = atoi(argv[3]);
	FILE* in = fopen(argv[1], "r");
	if (!in) {
		perror(argv[1]);
		return 2;
	}

	b2WorldDef wdef = b2DefaultWorldDef();
	wdef.gravity = b2Vec2_zero;
	wdef.workerCount = 1;
	wdef.enableSleep = false;
	b2WorldId world = b2CreateWorld(&wdef);
	b2ShapeDef shape = b2DefaultShapeDef();

	Swimmers fish = { 0 };
	Bodies balls = { 0 };
	float length = 0.0f, width = 0.0f;
	char line[512];
	const float mm = 0.001f;
	while (fgets(line, sizeof line, in)) {
		float a, b, c, d, e;
		if (sscanf(line, "field %f %f", &a, &b) == 2) {
			length = a * mm;
			width = b * mm;
		} else if (sscanf(line, "fish %f %f %f %f %f", &a, &b, &c, &d, &e) == 5) {
			b2BodyDef def = b2DefaultBodyDef();
			def.type = b2_dynamicBody;
			def.position = (b2Vec2){ a * mm, b * mm };
			def.rotation = b2MakeRot(c);
			b2BodyId body = b2CreateBody(world, &def);
			b2Capsule head = { { -0.0575f, 0.0f }, { 0.0875f, 0.0f }, 0.0225f }; /* x -80..110 mm, 45 mm wide */
			b2Capsule tail = { { -0.330f, 0.0f }, { -0.080f, 0.0f }, 0.014f };   /* x -344..-66 mm, 28 mm wide */
			b2CreateCapsuleShape(body, &shape, &head);
			b2CreateCapsuleShape(body, &shape, &tail);
			if (fish.count == fish.capacity)
				fish.items = grow(fish.items, &fish.capacity, sizeof *fish.items);
			fish.items[fish.count++] = (Swimmer){ body, d * mm, e };
		} else if (sscanf(line, "ball %f %f %f %f %f", &a, &b, &c, &d, &e) == 5) {
			b2BodyDef def = b2DefaultBodyDef();
			def.type = b2_dynamicBody;
			def.position = (b2Vec2){ a * mm, b * mm };
			def.linearVelocity = (b2Vec2){ c * mm, d * mm };
			b2BodyId body = b2CreateBody(world, &def);
			b2Circle round = { b2Vec2_zero, e * mm };
			b2CreateCircleShape(body, &shape, &round);
			if (balls.count == balls.capacity)
				balls.items = grow(balls.items, &balls.capacity, sizeof *balls.items);
			balls.items[balls.count++] = body;
		} else if (sscanf(line, "rect %f %f %f %f %f", &a, &b, &c, &d, &e) == 5) {
			b2Polygon box = b2MakeBox(0.5f * c * mm, 0.5f * d * mm);
			b2CreatePolygonShape(fixed_body(world, (b2Vec2){ a * mm, b * mm }, e), &shape, &box);
		} else if (sscanf(line, "round %f %f %f", &a, &b, &c) == 3) {
			b2Circle round = { b2Vec2_zero, c * mm };
			b2CreateCircleShape(fixed_body(world, (b2Vec2){ a * mm, b * mm }, 0.0f), &shape, &round);
		} else if (sscanf(line, "goal %f %f %f %f", &a, &b, &c, &d) == 4) {
			b2Polygon box = b2MakeBox(0.5f * (c - a) * mm, 0.5f * (d - b) * mm);
			b2CreatePolygonShape(fixed_body(world, (b2Vec2){ 0.5f * (a + c) * mm, 0.5f * (b + d) * mm }, 0.0f), &shape, &box);
		}
	}
	fclose(in);
	if (length <= 0.0f || fish.count + balls.count == 0) {
		fprintf(stderr, "crowd_cpu: %s has no field or no bodies\n", argv[1]);
		return 2;
	}

	/* The pool's walls: four static boxes, 1 m thick, outside the field. */
	b2BodyId pool = fixed_body(world, b2Vec2_zero, 0.0f);
	float hx = 0.5f * length, hy = 0.5f * width, t = 0.5f;
	b2Polygon walls[4] = {
		b2MakeOffsetBox(hx + 2.0f * t, t, (b2Vec2){ 0.0f, -hy - t }, b2Rot_identity),
		b2MakeOffsetBox(hx + 2.0f * t, t, (b2Vec2){ 0.0f, hy + t }, b2Rot_identity),
		b2MakeOffsetBox(t, hy + 2.0f * t, (b2Vec2){ -hx - t, 0.0f }, b2Rot_identity),
		b2MakeOffsetBox(t, hy + 2.0f * t, (b2Vec2){ hx + t, 0.0f }, b2Rot_identity),
	};
	for (int i = 0; i < 4; i++)
		b2CreatePolygonShape(pool, &shape, &walls[i]);

	double* cpu = malloc(sizeof(double) * (size_t)measure);
	double* wall = malloc(sizeof(double) * (size_t)measure);
	for (int step = 0; step < warm + measure; step++) {
		for (int i = 0; i < fish.count; i++) {
			Swimmer* s = &fish.items[i];
			b2Rot q = b2Body_GetRotation(s->id);
			b2Body_SetLinearVelocity(s->id, (b2Vec2){ s->speed * q.c, s->speed * q.s });
			b2Body_SetAngularVelocity(s->id, s->turn);
		}
		for (int i = 0; i < balls.count; i++) {
			b2Vec2 v = b2Body_GetLinearVelocity(balls.items[i]);
			float speed = b2Length(v);
			if (speed > 0.0f) {
				float left = fmaxf(0.0f, speed - 0.1f * drag(speed));
				b2Body_SetLinearVelocity(balls.items[i], b2MulSV(left / speed, v));
			}
		}
		double c0 = seconds_of(CLOCK_THREAD_CPUTIME_ID), w0 = seconds_of(CLOCK_MONOTONIC);
		b2World_Step(world, 0.1f, 4);
		double c1 = seconds_of(CLOCK_THREAD_CPUTIME_ID), w1 = seconds_of(CLOCK_MONOTONIC);
		if (step >= warm) {
			cpu[step - warm] = 1e3 * (c1 - c0);
			wall[step - warm] = 1e3 * (w1 - w0);
		}
	}
	printf("b2crowd %d %.4f %.4f\n", fish.count + balls.count, median_of(cpu, measure), median_of(wall, measure));
	b2DestroyWorld(world);
	free(cpu);
	free(wall);
	free(fish.items);
	free(balls.items);
	return 0;
}
