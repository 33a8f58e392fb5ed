/*
 * Copyright 2022 Ingemar Hedvall
 * SPDX-License-Identifier: MIT
 */

#include "littlebuffer.h"

namespace mdf {}  // namespace mdf