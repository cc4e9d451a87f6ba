#pragma once
// Hand loading and lookup in one include, for existing callers: load_hand and HandLoadOptions
// (hand_description.h), shipped hands and resolve_hand_path (assets.h).
#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/hand_description.h"
