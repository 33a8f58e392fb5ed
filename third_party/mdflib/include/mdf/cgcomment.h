/*
* Copyright 2025 Ingemar Hedvall
* SPDX-License-Identifier: MIT
 */

#pragma once

#include "mdf/mdcomment.h"

namespace mdf {

class CgComment : public MdComment {
 public:
  CgComment();

};

}  // namespace mdf


