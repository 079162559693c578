<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>Language</name>
    <message>
        <location filename="../ui/language.cpp" line="16"/>
        <source>System Default</source>
        <translation>Как в системе</translation>
    </message>
</context>
<context>
    <name>carom::ui::AccuracyWindow</name>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="41"/>
        <source>Speed vs accuracy</source>
        <translation>Скорость и точность</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="43"/>
        <source>Position error against exact (m)</source>
        <translation>Ошибка положения относительно exact (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="43"/>
        <source>Relative energy drift</source>
        <translation>Относительный дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="44"/>
        <source>Deepest penetration (m)</source>
        <translation>Максимальная глубина проникновения (m)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="44"/>
        <source>Escaped balls</source>
        <translation>Вылетевшие шары</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="50"/>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Computing time (s)</source>
        <translation>Время вычислений (s)</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Run</source>
        <translation>Прогон</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="73"/>
        <source>Position error</source>
        <translation>Ошибка положения</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Energy drift</source>
        <translation>Дрейф энергии</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Penetration</source>
        <translation>Проникновение</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="74"/>
        <source>Escaped</source>
        <translation>Вылетело</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="81"/>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="83"/>
        <source>Apply Selected Settings</source>
        <translation>Применить выбранные настройки</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="90"/>
        <source>Each point is one run of the current scene; lower and further left is better. Choose a run to use its settings.</source>
        <translation>Каждая точка — один прогон текущей сцены; чем ниже и левее, тем лучше. Выберите прогон, чтобы применить его настройки.</translation>
    </message>
    <message>
        <location filename="../ui/accuracy_window.cpp" line="97"/>
        <source>Error:</source>
        <translation>Ошибка:</translation>
    </message>
</context>
<context>
    <name>carom::ui::EnergyPlot</name>
    <message>
        <location filename="../ui/energy_plot.cpp" line="31"/>
        <source>Kinetic</source>
        <translation>Кинетическая</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="32"/>
        <source>Potential</source>
        <translation>Потенциальная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="33"/>
        <source>Total</source>
        <translation>Полная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="34"/>
        <source>Simulated time (s)</source>
        <translation>Модельное время (s)</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="35"/>
        <source>Energy (J)</source>
        <translation>Энергия (J)</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="52"/>
        <source>Energy</source>
        <translation>Энергия</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="90"/>
        <location filename="../ui/main_window.cpp" line="95"/>
        <source>&amp;Run</source>
        <translation>&amp;Запуск</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="93"/>
        <source>Run or pause the simulation (Space)</source>
        <translation>Запустить или приостановить симуляцию (Пробел)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="95"/>
        <source>&amp;Pause</source>
        <translation>&amp;Пауза</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="99"/>
        <source>&amp;Step</source>
        <translation>&amp;Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="101"/>
        <source>Advance one time step (S)</source>
        <translation>Выполнить один шаг по времени (S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="107"/>
        <source>R&amp;eset</source>
        <translation>&amp;Сброс</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="109"/>
        <source>Back to the scene&apos;s initial state (R)</source>
        <translation>Вернуть сцену в начальное состояние (R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="115"/>
        <source>&amp;Full Screen</source>
        <translation>&amp;Полноэкранный режим</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="121"/>
        <source>&amp;Follow Ball</source>
        <translation>&amp;Следить за шаром</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="127"/>
        <source>&amp;Explosions</source>
        <translation>&amp;Взрывы</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="133"/>
        <source>&amp;Mute</source>
        <translation>Без &amp;звука</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="138"/>
        <source>Larger Time Step</source>
        <translation>Увеличить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="141"/>
        <source>Smaller Time Step</source>
        <translation>Уменьшить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="148"/>
        <source>Simulation</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="156"/>
        <source>Simulated seconds per real second</source>
        <translation>Секунд модели за секунду реального времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="163"/>
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="166"/>
        <source>Gravity %1 (m/s²)</source>
        <translation>Гравитация %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="172"/>
        <source>Step</source>
        <translation>Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="173"/>
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Шаг по времени в секундах (клавиши + и -)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="181"/>
        <source>Exact (event-driven), swept, or discrete steps</source>
        <translation>exact (по событиям), swept или discrete (фиксированные шаги)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="188"/>
        <source>Integrator of the swept and discrete methods</source>
        <translation>Интегратор для методов swept и discrete</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="195"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="198"/>
        <source>Speed vs &amp;Accuracy…</source>
        <translation>Скорость и &amp;точность…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="200"/>
        <source>&amp;Quit</source>
        <translation>&amp;Выход</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="202"/>
        <source>&amp;Examples</source>
        <translation>&amp;Примеры</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="213"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="218"/>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="228"/>
        <source>The language changes when Carom is next started.</source>
        <translation>Язык изменится при следующем запуске Carom.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="236"/>
        <source>%1 — Carom</source>
        <translation>%1 — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="307"/>
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   E = %6 J (drift %7)</source>
        <translation>t = %1 s   ×%2 от реального времени   %3 fps   столкновений/s: %4   шаров: %5   E = %6 J (дрейф %7)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="317"/>
        <source>   sound unavailable</source>
        <translation>   звук недоступен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="319"/>
        <source>   muted</source>
        <translation>   звук выключен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="320"/>
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — физика не успевает; замедленный ход</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/carom_main.cpp" line="123"/>
        <source>Collision physics sandbox</source>
        <translation>Песочница для физики столкновений</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="126"/>
        <source>Scene file to open</source>
        <translation>Файл сцены для открытия</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="129"/>
        <source>Save a picture of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="130"/>
        <source>file.png</source>
        <translation>файл.png</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="133"/>
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Сколько секунд выполнять симуляцию перед --screenshot.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="134"/>
        <source>seconds</source>
        <translation>секунды</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="136"/>
        <source>Language of the program (en, ru, de).</source>
        <translation>Язык программы (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="137"/>
        <source>code</source>
        <translation>код</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="140"/>
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Запустить газ из N шаров на 5 с при виде 1280x720, вывести время кадров и самую долгую задержку интерфейса и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="166"/>
        <source>Cannot open scene</source>
        <translation>Не удалось открыть сцену</translation>
    </message>
</context>
</TS>
