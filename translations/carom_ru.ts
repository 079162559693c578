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
        <location filename="../ui/energy_plot.cpp" line="35"/>
        <source>Kinetic</source>
        <translation>Кинетическая</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="36"/>
        <source>Potential</source>
        <translation>Потенциальная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="37"/>
        <source>Total</source>
        <translation>Полная</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="38"/>
        <source>Simulated time (s)</source>
        <translation>Модельное время (s)</translation>
    </message>
    <message>
        <location filename="../ui/energy_plot.cpp" line="39"/>
        <source>Energy (J)</source>
        <translation>Энергия (J)</translation>
    </message>
</context>
<context>
    <name>carom::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="53"/>
        <source>Energy</source>
        <translation>Энергия</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="94"/>
        <location filename="../ui/main_window.cpp" line="99"/>
        <source>&amp;Run</source>
        <translation>&amp;Запуск</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="97"/>
        <source>Run or pause the simulation (Space)</source>
        <translation>Запустить или приостановить симуляцию (Пробел)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="99"/>
        <source>&amp;Pause</source>
        <translation>&amp;Пауза</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="103"/>
        <source>&amp;Step</source>
        <translation>&amp;Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="105"/>
        <source>Advance one time step (S)</source>
        <translation>Выполнить один шаг по времени (S)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="111"/>
        <source>R&amp;eset</source>
        <translation>&amp;Сброс</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="113"/>
        <source>Back to the scene&apos;s initial state (R)</source>
        <translation>Вернуть сцену в начальное состояние (R)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="119"/>
        <source>&amp;Full Screen</source>
        <translation>&amp;Полноэкранный режим</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="125"/>
        <source>&amp;Follow Ball</source>
        <translation>&amp;Следить за шаром</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="131"/>
        <source>&amp;Explosions</source>
        <translation>&amp;Взрывы</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="138"/>
        <source>&amp;Antialiasing</source>
        <translation>&amp;Сглаживание</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="150"/>
        <source>&amp;Mute</source>
        <translation>Без &amp;звука</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="155"/>
        <source>Larger Time Step</source>
        <translation>Увеличить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="158"/>
        <source>Smaller Time Step</source>
        <translation>Уменьшить шаг по времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="165"/>
        <source>Simulation</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="172"/>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="173"/>
        <source>Simulated seconds per real second</source>
        <translation>Секунд модели за секунду реального времени</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="180"/>
        <source>Gravity</source>
        <translation>Гравитация</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="183"/>
        <source>Gravity %1 (m/s²)</source>
        <translation>Гравитация %1 (m/s²)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="189"/>
        <source>Step</source>
        <translation>Шаг</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="190"/>
        <source>Time step in seconds (+ and - keys)</source>
        <translation>Шаг по времени в секундах (клавиши + и -)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="198"/>
        <source>Exact (event-driven), swept, or discrete steps</source>
        <translation>exact (по событиям), swept или discrete (фиксированные шаги)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="205"/>
        <source>Integrator of the swept and discrete methods</source>
        <translation>Интегратор для методов swept и discrete</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="212"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Симуляция</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="215"/>
        <source>Speed vs &amp;Accuracy…</source>
        <translation>Скорость и &amp;точность…</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="217"/>
        <source>&amp;Quit</source>
        <translation>&amp;Выход</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="219"/>
        <source>&amp;Examples</source>
        <translation>&amp;Примеры</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="230"/>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="236"/>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="246"/>
        <source>The language changes when Carom is next started.</source>
        <translation>Язык изменится при следующем запуске Carom.</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="254"/>
        <source>%1 — Carom</source>
        <translation>%1 — Carom</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="334"/>
        <source>t = %1 s   ×%2 real time   %3 fps   %4 collisions/s   %5 balls   E = %6 J (drift %7)</source>
        <translation>t = %1 s   ×%2 от реального времени   %3 fps   столкновений/s: %4   шаров: %5   E = %6 J (дрейф %7)</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="344"/>
        <source>   sound unavailable</source>
        <translation>   звук недоступен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="346"/>
        <source>   muted</source>
        <translation>   звук выключен</translation>
    </message>
    <message>
        <location filename="../ui/main_window.cpp" line="347"/>
        <source>   — the physics cannot keep up; running slower</source>
        <translation>   — физика не успевает; замедленный ход</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/carom_main.cpp" line="125"/>
        <source>Collision physics sandbox</source>
        <translation>Песочница для физики столкновений</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="128"/>
        <source>Scene file to open</source>
        <translation>Файл сцены для открытия</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="131"/>
        <source>Save a picture of the window and quit.</source>
        <translation>Сохранить снимок окна и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="132"/>
        <source>file.png</source>
        <translation>файл.png</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="135"/>
        <source>Run the simulation this long before --screenshot.</source>
        <translation>Сколько секунд выполнять симуляцию перед --screenshot.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="136"/>
        <source>seconds</source>
        <translation>секунды</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="138"/>
        <source>Language of the program (en, ru, de).</source>
        <translation>Язык программы (en, ru, de).</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="139"/>
        <source>code</source>
        <translation>код</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="142"/>
        <source>Run a gas of N balls for 5 s with the view at 1280x720, print frame times and the longest GUI stall, and quit.</source>
        <translation>Запустить газ из N шаров на 5 с при виде 1280x720, вывести время кадров и самую долгую задержку интерфейса и выйти.</translation>
    </message>
    <message>
        <location filename="../app/carom_main.cpp" line="168"/>
        <source>Cannot open scene</source>
        <translation>Не удалось открыть сцену</translation>
    </message>
</context>
</TS>
