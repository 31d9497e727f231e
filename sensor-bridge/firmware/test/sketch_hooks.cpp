// Compiles hapticon_ref.ino as the Arduino IDE would: as C++, with Arduino.h included first.
#include "Arduino.h"

#include "../hapticon_ref/hapticon_ref.ino"
