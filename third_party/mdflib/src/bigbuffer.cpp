//
// Created by ihedv on 2022-09-22.
//

#include "bigbuffer.h"

namespace mdf {}  // namespace mdf