#pragma once
// What every exercise kind does the same way, one file per job: its instance's identity (solve
// input, solution, fingerprint), its questions with the sheet's fields and the key's lines, its
// sections and figures' views, the drawing of random data, and the values of its worked steps.
// A kind only says what is specific to it: how to draw, the method, the texts, the diagrams.
#include "exercises/instance_draw.h"
#include "exercises/instance_identity.h"
#include "exercises/questions.h"
#include "exercises/sections.h"
#include "exercises/step_text.h"
