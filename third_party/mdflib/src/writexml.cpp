/*
 * Copyright 2022 Ingemar Hedvall
 * SPDX-License-Identifier: MIT
 */
// #include "writexml.h"

namespace mdf {}  // namespace mdf